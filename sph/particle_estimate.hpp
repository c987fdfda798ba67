#pragma once
// The particle counts and heap bytes of an SPH scene, estimated before any particle is made.

#include "io/types.hpp"

#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// Heap bytes per particle of a built SPH solver (SphSolver::bytes(): particle fields, work
/// arrays, neighbour list), measured with `bench/sph_throughput 100000` on a 3D elastic block
/// of 1e5 particles (cubic spline, h = 1.3 spacing, about 37 neighbours): 903 bytes per
/// particle with the updated-Lagrangian formulation (cell list and Verlet list alike), 1843
/// with the total-Lagrangian one, which also stores its reference pairs; the process peaked at
/// 90 MiB resident, 943 bytes per particle (docs/validation/stability.md). Frames and the OS
/// add to it, so a scene refused on these figures would not have fitted.
inline constexpr double kSolverBytesPerParticle = 903.0;
inline constexpr double kTotalLagrangianBytesPerParticle = 1843.0;

/// What one [[sph.body]] or [[sph.wall]] would hold, estimated before any particle is made.
struct ParticleCount {
    std::string table;       ///< "sph.body[0]", "sph.wall[2]"
    int index = 0;           ///< its place in [[sph.body]] or [[sph.wall]]
    std::string name;        ///< its `name`
    std::string spacing_key; ///< the key whose value sets its spacing ("sph.body[0].spacing")
    double spacing = 0.0;    ///< m
    double particles = 0.0;  ///< estimated count (a double: it may be far beyond any integer)
    std::string basis;       ///< how it was estimated ("0.1 x 0.1 x 0.2 m box / spacing^3")
};

/// The particle counts of a case's SPH scene ([sph] with [[sph.body]], [[sph.source]] and
/// [[sph.wall]]; the
/// walls that [[coupling.interface]] lays on shells are not counted) from the shapes' volumes
/// (bodies: volume / spacing^dimension; box shapes exactly as the lattice rounds them; mesh
/// shapes: the enclosed volume of the surface; LS-DYNA decks: their *ELEMENT_SPH cards) and
/// the walls' areas (area / wall spacing^(dimension-1) per layer). Nothing is allocated in
/// proportion to the counts. Reads the same keys with the same checks as the builders, so a
/// bad key fails with the message it would get there.
struct ParticleEstimate {
    std::vector<ParticleCount> bodies;
    /// [[sph.source]]: a site per particle of its box or shape at the bodies' spacing (a
    /// source creates at least that many).
    std::vector<ParticleCount> sources;
    std::vector<ParticleCount> walls;

    double total() const;
    /// The body or wall holding the most particles (nullptr when there is none).
    const ParticleCount* largest() const;
    /// kSolverBytesPerParticle, or kTotalLagrangianBytesPerParticle for that formulation.
    double bytes_per_particle = kSolverBytesPerParticle;
    /// Heap bytes of the SPH solver for total() particles.
    double bytes() const { return total() * bytes_per_particle; }
};

/// The estimate of the [sph] table of `root` (empty when there is none). `dimension` 2 or 3.
ParticleEstimate estimate_particles(const io::CaseTable& root, int dimension);

} // namespace grainload::sph
