#pragma once
// The readers of a case's [sph] tables: solver options, walls, clamps, friction, symmetry.

#include "sph/particle_set.hpp"
#include "sph/phase_sequence.hpp"
#include "sph/rigid_wall.hpp"
#include "sph/sph_options.hpp"

#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// Solver settings of an [sph] table with particle interactions (see docs/user-guide/sph.md):
/// kernel, smoothing_length_ratio, cfl_safety, verlet_skin, kernel_gradient_correction and
/// the [sph.artificial_viscosity], [sph.artificial_stress] and [sph.contact] tables.
/// `spacing` is the bodies' particle spacing, gravity comes from [case].
SphOptions read_sph_options(const io::CaseTable& sph, int dimension, double spacing,
                            const Vec3& gravity);

/// Append the particles of every [[sph.wall]] to `particles` and return the walls. Wall body
/// ids follow `first_body_id`; `support_radius` sets the default number of layers. `phases`
/// (null: none) are what remove_at and history_start = "phase:NAME" may name; the walls get
/// the phases' starts from SphModel.
std::vector<Wall> read_rigid_walls(const io::CaseTable& sph, ParticleSet& particles, int dimension,
                                   double spacing, double support_radius, int first_body_id,
                                   const PhaseSequence* phases = nullptr);

/// The [[sph.body.clamp]] boxes (`min`, `max`) of one body, whose particles are
/// particles[first, size()): every particle inside one of them (boundary included) is flagged
/// clamped. A box that holds none of the body's particles is refused.
void read_clamps(const io::CaseTable& body, ParticleSet& particles, Index first, int dimension);

/// The optional [sph.body.initial_stress] of one body (particles[first, size())):
/// `type = "geostatic"` with `lateral_ratio` K0 in [0, 2] (sph/initial_stress.hpp). Needs gravity.
void read_initial_stress(const io::CaseTable& body, ParticleSet& particles, Index first,
                         const Vec3& gravity, double spacing);

/// Index into `body_names` of the [[sph.body]] that `table`'s `key` names; an unknown name fails
/// with the known ones listed (file:line, exit code 2).
int body_index(const io::CaseTable& table, const std::string& key,
               const std::vector<std::string>& body_names);

/// The [[sph.friction]] pairs: `body` and `wall` by name, `mu_static` >= `mu_kinetic` >= 0.
/// Body ids are indices into `body_names`; walls carry their own.
std::vector<FrictionPair> read_friction_pairs(const io::CaseTable& sph,
                                              const std::vector<std::string>& body_names,
                                              const std::vector<Wall>& walls);

/// The [[sph.symmetry]] planes (`axis` x, y or z, `at`, optional `side`; at most one per axis,
/// z only in 3D), checked against the scene built so far: every material particle must lie on
/// the material side, at least a quarter spacing off the plane. A wall that comes within
/// `support_radius` of a plane on the material side either ends at it (within a quarter
/// spacing; it is then mirrored across it: Wall::mirror_planes) or runs on past it by at least
/// `support_radius` - `spacing` (not mirrored); one in between is refused.
std::vector<SymmetryPlane>
read_symmetry_planes(const io::CaseTable& sph, const ParticleSet& particles,
                     std::vector<Wall>& walls, const std::vector<std::string>& body_names,
                     int dimension, double spacing, double support_radius);

} // namespace grainload::sph
