#pragma once
// The particle counts and heap bytes of an SPH scene, estimated before any particle is made.

#include "io/surface_mesh.hpp"
#include "io/types.hpp"
#include "sph/body_shape_reader.hpp"

#include <string>
#include <vector>

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
/// [[sph.wall]]; the walls that [[coupling.interface]] lays on shells are not counted) from the
/// shapes' volumes (count_shape) and the walls' areas (area / wall spacing^(dimension-1) per
/// layer). Nothing is allocated in proportion to the counts. The bodies, shapes and wall
/// layouts are read by the readers the run builds them with (estimate_particles,
/// sph/particle_estimate_reader.hpp), so a bad key fails with the message it gets there.
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

/// The particles a shape holds: box shapes exactly as the lattice of fill_box rounds them
/// (max(1, round(edge / spacing)) cells per axis); cylinders and cones from the frustum's
/// volume (3D) or axial section (2D), discs from their area; mesh shapes from the enclosed
/// volume of the surface; LS-DYNA decks: their particles.
ParticleCount count_shape(const ShapeSettings& shape, double spacing, int dimension);
/// A box from `lower` to `upper` filled at `spacing`, as count_shape counts a box shape.
ParticleCount count_box(const Vec3& lower, const Vec3& upper, double spacing, int dimension);
/// Volume enclosed by a closed surface (divergence theorem over its triangles, quadrangles
/// split along a diagonal).
double enclosed_volume(const io::SurfaceMesh& mesh);
/// Surface area of a mesh (3D) or length of its polyline (2D).
double surface_measure(const io::SurfaceMesh& mesh, int dimension);
/// A figure of an estimate's basis, to three digits.
std::string estimate_text(double value);

} // namespace grainload::sph
