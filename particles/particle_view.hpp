#pragma once
// The fields every particle method's set carries, as read-only spans: what scene parts read.

#include "io/types.hpp"

#include <span>

namespace grainload::particles {

/// A read-only view of a particle set's common fields, indexed by particle: what a scene part
/// that works on any particle method (SPH, DEM) reads. Valid until particles leave or enter.
struct ParticleView {
    std::span<const Vec3> position;
    std::span<const double> mass;
    std::span<const int> body_id;
    /// The wall a particle belongs to, -1 for a material particle; empty when the method's walls
    /// are not made of particles.
    std::span<const int> wall_id;

    Index size() const { return static_cast<Index>(position.size()); }
    bool is_wall(Index i) const {
        return !wall_id.empty() && wall_id[static_cast<std::size_t>(i)] >= 0;
    }
};

} // namespace grainload::particles
