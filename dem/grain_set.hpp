#pragma once
// The DEM's particles: rigid grains, each one sphere or a clump of spheres, as named fields.

#include "io/types.hpp"
#include "particles/particle_view.hpp"

#include <Eigen/Geometry>
#include <cstdint>
#include <span>
#include <vector>

namespace grainload::dem {

/// Rigid grains in structure-of-arrays form, one entry per grain in every field: what the
/// equations of motion integrate. A grain's surface is its spheres (dem/sphere_set.hpp): one
/// for a spherical grain, several for a clump. `id` is given at creation and never reused
/// (compaction keeps the order, so index order is id order).
struct GrainSet {
    std::vector<std::uint64_t> id;
    std::vector<int> body_id;
    std::vector<double> mass;
    /// Principal moments of inertia in the grain's own frame; zero for a grain whose body does
    /// not rotate. A sphere's three are equal, 2/5 m r^2.
    std::vector<Vec3> inertia;
    std::vector<Vec3> position; ///< the centre of mass
    std::vector<Vec3> velocity;
    std::vector<Vec3> angular_velocity;
    /// From the grain's own frame (its principal axes) to the scene's.
    std::vector<Eigen::Quaterniond> orientation;
    std::vector<Vec3> force;  ///< contacts and gravity at the last evaluation
    std::vector<Vec3> torque; ///< about the centre of mass, at the last evaluation
    std::uint64_t next_id = 0;

    Index size() const { return static_cast<Index>(id.size()); }
    /// Append a grain at rest; returns its index.
    Index add(int body, double grain_mass, const Vec3& moments, const Vec3& at,
              const Eigen::Quaterniond& turned);
    /// Whether grain i turns as a sphere does: equal principal moments, so that omega follows
    /// the torque with no gyroscopic term.
    bool isotropic(Index i) const {
        const Vec3& m = inertia[static_cast<std::size_t>(i)];
        return m.x() == m.y() && m.y() == m.z();
    }
    /// The inertia tensor of grain i in the scene's frame, R diag(I) R^T.
    Mat3 world_inertia(Index i) const;
    /// The grains' mass, summed in index order.
    double total_mass() const;
    /// Keep the grains whose `gone` flag is 0, in order, in every field.
    void keep(std::span<const char> gone);
    /// The common fields the scene parts read.
    particles::ParticleView view() const { return {position, mass, body_id, {}}; }
};

} // namespace grainload::dem
