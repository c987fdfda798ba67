#pragma once
// Where a scene's material can get to, found before the run, and the outlets it cannot reach.

#include "io/region.hpp"
#include "particles/sink.hpp"
#include "sph/particle_set.hpp"
#include "sph/scene_places.hpp"
#include "sph/source.hpp"
#include "sph/wall.hpp"

#include <array>
#include <string>
#include <vector>

namespace grainload::sph {

/// Where the material of a scene can get to, found before the run on a grid of cells a particle
/// spacing wide: a flood from the cells its bodies' particles and its sources' sites start in,
/// from cell to face-adjacent cell, through every cell that no particle of a wall that stays
/// covers (with the cube of its spacing), and never upwards against gravity. A wall stays unless it
/// is removed (remove_at), moved by a prescribed rigid motion or acts on some bodies only: those
/// may let material by (a coupled shell deflects but stays). Material that starts at rest among
/// walls that stay does not climb; an initial velocity (a body's or a source's) or a moving rigid
/// wall lifts that rule. The flood spreads sideways without limit, so it covers more than the
/// material will: a region outside it is out of reach of every particle.
class ReachMap {
  public:
    /// The flood of body `body`'s particles and sources (-1: every body's); `regions` are
    /// taken into the grid (a sink's box; a plane sink's point and the cells beyond it).
    ReachMap(const ParticleSet& particles, const std::vector<Wall>& walls, const SourceSet& sources,
             const std::vector<io::Region>& regions, const Vec3& gravity, double spacing,
             int dimension, int body);
    /// Whether a flooded cell meets `region`.
    bool reaches(const io::Region& region) const;
    /// Whether the cell of `x` is flooded.
    bool reaches(const Vec3& x) const;

  private:
    using Cell = std::array<Index, 3>;
    Cell cell_of(const Vec3& x) const;
    /// Cells of about `spacing` over the box [lower, upper] (coarser where they would be too
    /// many); false when the box is not finite.
    bool lay_grid(const Vec3& lower, const Vec3& upper, double spacing);
    /// Blocks the cells a wall particle at `x` of spacing `size` covers.
    void block(const Vec3& x, double size);
    Index index(const Cell& c) const { return (c[2] * count_[1] + c[1]) * count_[0] + c[0]; }
    Vec3 centre(const Cell& c) const;
    void flood(std::vector<Index>& front, bool climb, const Vec3& up);

    int dimension_ = 3;
    Vec3 origin_ = Vec3::Zero();
    double cell_ = 0.0;
    Cell count_{1, 1, 1};
    bool everywhere_ = false; ///< a scene too far out for a grid: every region counts as reached
    std::vector<char> blocked_;
    std::vector<char> flooded_;
};

/// Warnings, each at its key of the [sph] table `sph`, for what no material can reach: a sink
/// (whose outlet_width would give `grainload check` a Beverloo discharge that never comes)
/// and a wall due to be removed (a gate that releases nothing). `walls` are the solver's, the
/// [[sph.wall]] tables' first.
std::vector<std::string>
outlet_reach_warnings(const ScenePlaces& places, const ParticleSet& particles,
                      const std::vector<Wall>& walls, const particles::SinkSet& sinks,
                      const SourceSet& sources, const Vec3& gravity, double spacing, int dimension);

} // namespace grainload::sph
