#pragma once
// The readers of a case's [sph] tables: solver options, walls, clamps, friction, symmetry,
// periodic axes.

#include "io/key_spec.hpp"
#include "particles/phase_sequence.hpp"
#include "sph/heap_monitor.hpp"
#include "sph/particle_set.hpp"
#include "sph/probes.hpp"
#include "sph/rigid_wall.hpp"
#include "sph/scene_places.hpp"
#include "sph/sph_options.hpp"
#include "sph/surface_mesh_wall.hpp"

#include <array>
#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// The keys of [sph] (docs/user-guide/sph.md, "Key tables"); the defaults are SphOptions' own,
/// which tests/unit/sph/sph_keys_test.cpp holds equal to these.
inline constexpr std::array<io::KeySpec, 9> kSphKeys{{
    {"interactions", "boolean", "true",
     "false: particles fly freely under gravity (needs time_step), a pipeline check", 1.0},
    {"time_step", "time", "the CFL limit",
     "a fixed step; refused, naming the limit, when above the CFL limit"},
    {"kernel", "`cubic_spline`, `quintic_spline` or `wendland_c2`", "cubic_spline",
     "the smoothing kernel"},
    {"smoothing_length_ratio", "number in [0.8, 3]", "1.3",
     "h / spacing (the Wendland C2 kernel wants about 2)", 1.3},
    {"cfl_safety", "number in (0, 1]", "0.3", "the step is cfl_safety h / (c + abs(v))", 0.3},
    {"verlet_skin", "number in [0, 1]", "0.1",
     "the neighbour list's skin as a fraction of h; 0: a cell list every step", 0.1},
    {"kernel_gradient_correction", "boolean", "true",
     "exact linear gradients, angular momentum conserved (always on in total_lagrangian)", 1.0},
    {"formulation", "`updated_lagrangian` or `total_lagrangian`", "updated_lagrangian",
     "sums over current neighbours, or over each body's initial configuration (solids only)"},
    {"fluidity_interval", "time >= 0", "1e-4 s",
     "the non-local fluidity's field is solved once in each such interval; 0: every step", 1e-4},
}};

/// The keys of [sph.artificial_viscosity] (Monaghan's Pi_ij); without the table: none.
inline constexpr std::array<io::KeySpec, 3> kArtificialViscosityKeys{{
    {"alpha", "number >= 0", "0", "the linear term alpha c mu", 0.0},
    {"beta", "number >= 0", "0", "the quadratic term beta mu^2", 0.0},
    {"sound_speed", "velocity >= 0", "the materials' own",
     "the c of alpha c mu; default: the materials' wave speed before their stiffness_scale"},
}};

/// The keys of [sph.artificial_stress] (Gray, Monaghan & Swift 2001); without the table: none.
inline constexpr std::array<io::KeySpec, 2> kArtificialStressKeys{{
    {"epsilon", "number >= 0", "0", "the fraction of the tensile principal stresses", 0.0},
    {"exponent", "number > 0", "4", "the exponent of the kernel ratio", 4.0},
}};

/// The keys of [sph.contact], the potential between bodies and with walls; without it: none.
inline constexpr std::array<io::KeySpec, 3> kContactKeys{{
    {"stiffness", "pressure > 0", "", "K; about 100 E for impacts"},
    {"exponent", "number >= 1", "1", "n of the potential", 1.0},
    {"damping_ratio", "number in [0, 10]", "0",
     "zeta: the normal dashpot as a fraction of critical damping", 0.0},
}};

/// The keys of each [[sph.friction]] table: Coulomb friction of one body on one wall.
inline constexpr std::array<io::KeySpec, 4> kFrictionKeys{{
    {"body", "string", "", "a [[sph.body]] name"},
    {"wall", "string", "", "a [[sph.wall]] name"},
    {"mu_static", "number >= 0", "", "stick while the tangential force needed <= mu_static N"},
    {"mu_kinetic", "number in [0, mu_static]", "mu_static", "slide with mu_kinetic N"},
}};

/// The keys of [sph.body.initial_stress]; without the table the body starts stress-free.
inline constexpr std::array<io::KeySpec, 2> kInitialStressKeys{{
    {"type", "`geostatic`", "",
     "sigma_v = -rho abs(g) depth below the body's top, K0 sigma_v horizontally"},
    {"lateral_ratio", "number in [0, 2]", "", "K0 = sigma_h / sigma_v (Jaky: 1 - sin phi)"},
}};

/// The keys of each [[sph.body.clamp]] box: the body's particles inside it are held.
inline constexpr std::array<io::KeySpec, 2> kClampKeys{{
    {"min", "length vector", "", "the box's lower corner (faces included)"},
    {"max", "length vector", "", "the box's upper corner, above min in every direction"},
}};

/// The keys of [[sph.wall]] that open an outlet or time a gate (docs/user-guide/sph.md,
/// "Outlets and gates").
inline constexpr std::array<io::KeySpec, 2> kWallOutletKeys{{
    {"remove_at", "time, `settled` or `phase:NAME`", "never",
     "the wall leaves the scene at the end of the first step that reaches this time, that "
     "settles the scene ([sph.settle]), or that begins the phase ([[phase]])"},
    {"history_start", "time or `phase:NAME`", "0 s",
     "the time velocity_history and angular_velocity_history count from; until then the wall "
     "holds their first values"},
}};

/// The keys of each [[sph.wall]] but its outlet keys (kWallOutletKeys) and a mesh wall's file
/// (io::kSurfaceMeshKeys).
inline constexpr std::array<io::KeySpec, 18> kWallKeys{{
    {"name", "string", "", "names the wall in wall_forces.csv, frames and summary.json"},
    {"type", "`plane`, `box` or `mesh`", "", "the wall's geometry"},
    {"origin", "length vector", "required for a plane", "a corner of the plane"},
    {"edge_u", "length vector", "required for a plane", "the plane is origin + s edge_u"},
    {"edge_v", "length vector", "required for a plane in 3D", "+ t edge_v, s and t in [0, 1]"},
    {"normal", "vector", "required for a plane", "points into the material"},
    {"min", "length vector", "required for a box", "the box's inner lower corner"},
    {"max", "length vector", "required for a box", "the box's inner upper corner"},
    {"open_top", "boolean", "true", "a box without its top face", 1.0},
    {"flip_normals", "boolean", "false", "a mesh wall: the material is behind every face", 0.0},
    {"spacing", "length", "the bodies' spacing",
     "wall particle spacing, 0.2 to 1 times the bodies'"},
    {"layers", "integer in [1, 20]", "ceil(2h / spacing)", "layers of wall particles"},
    {"velocity", "velocity vector", "0 m/s", "the prescribed rigid motion of the centre"},
    {"angular_velocity", "angular velocity vector", "0 rad/s", "the rotation about the centre"},
    {"velocity_history", "list of [time, velocity vector]", "none",
     "instead of velocity: piecewise linear in time, held outside its points"},
    {"angular_velocity_history", "list of [time, angular velocity vector]", "none",
     "instead of angular_velocity, likewise"},
    {"centre", "length vector", "the wall particles' centroid", "the centre of the rotation"},
    {"bodies", "string or list of strings", "every body",
     "the [[sph.body]] names it acts on; the others pass through it"},
}};

/// Solver settings of an [sph] table with particle interactions (see docs/user-guide/sph.md):
/// kernel, smoothing_length_ratio, cfl_safety, verlet_skin, kernel_gradient_correction and
/// the [sph.artificial_viscosity], [sph.artificial_stress] and [sph.contact] tables.
/// `spacing` is the bodies' particle spacing, gravity comes from [case].
SphOptions read_sph_options(const io::CaseTable& sph, int dimension, double spacing,
                            const Vec3& gravity);

/// How a wall's particles are laid, as [[sph.wall]] and [[coupling.interface]] state it.
struct WallLayout {
    double spacing = 0.0; ///< m
    int layers = 0;
};

/// A wall table's `spacing` (default the bodies' `body_spacing`, refused outside 0.2 to 1 times
/// it: a coarser wall lets particles through, a much finer one only costs) and `layers`
/// (default enough to fill the kernel's `support_radius`, refused outside 1 to 20).
WallLayout read_wall_layout(const io::CaseTable& wall, double body_spacing, double support_radius);

/// Append the particles of every [[sph.wall]] to `particles` and return the walls. Wall body
/// ids follow `first_body_id`; `support_radius` sets the default number of layers. `phases`
/// (null: none) are what remove_at and history_start = "phase:NAME" may name; the walls get
/// the phases' starts from SphModel.
std::vector<Wall> read_rigid_walls(const io::CaseTable& sph, ParticleSet& particles, int dimension,
                                   double spacing, double support_radius, int first_body_id,
                                   const particles::PhaseSequence* phases = nullptr);

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

/// [sph.heap]: `body` by name, `origin`, `rest_fraction` in (0, 1); refused without gravity (the
/// heap is measured along it).
HeapSettings read_heap_settings(const io::CaseTable& heap,
                                const std::vector<std::string>& body_names, const Vec3& gravity);

/// The [[sph.probe]] tables: `name` and `position` each.
std::vector<ProbeSettings> read_probe_settings(const io::CaseTable& sph);

/// Coulomb's coefficients of a body against a wall or shell part.
struct CoulombCoefficients {
    double mu_static = 0.0;
    double mu_kinetic = 0.0;
};

/// A friction table's `mu_static` (>= 0) and `mu_kinetic` (default `mu_static`, refused above
/// it: kinetic friction does not exceed static), as [[sph.friction]] and [[coupling.friction]]
/// state them.
CoulombCoefficients read_coulomb_coefficients(const io::CaseTable& table);

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

/// The [[sph.periodic]] axes (`axis` x, y or z, `min`, `max`; at most one per axis, none on an
/// axis of a symmetry plane, z only in 3D), checked against the scene built so far: the period
/// longer than twice `search_radius`, every body and wall inside [min, max), and the particles
/// of a body or wall that reaches both ends at least half its lattice step apart across the
/// seam.
std::vector<PeriodicAxis> read_periodic_axes(const io::CaseTable& sph, const ParticleSet& particles,
                                             const std::vector<Wall>& walls,
                                             const std::vector<std::string>& body_names,
                                             const std::vector<SymmetryPlane>& planes,
                                             int dimension, double search_radius);

/// A wall table's optional `bodies` key: one [[sph.body]] name or a list of them, as body ids
/// (indices into `body_names`). Absent: empty (all bodies). An unknown name, an empty list or
/// a name given twice fails at the key (file:line, exit code 2).
std::vector<int> read_wall_bodies(const io::CaseTable& table,
                                  const std::vector<std::string>& body_names);

/// mesh_wall_points for a [[sph.wall]] of type = "mesh": the mesh of its `file` (see
/// io::read_surface_mesh), with the wall's `flip_normals` as its reader read it. Refused when
/// the mesh has no faces (3D) or no line segments (plane strain).
MeshWallSamples read_mesh_wall_points(const io::CaseTable& wall, int dimension, double spacing,
                                      int layers, bool flip_normals);

/// Where the scene's start checks will point (sph/scene_places.hpp), from the case's root.
ScenePlaces read_scene_places(const io::CaseTable& root);

} // namespace grainload::sph
