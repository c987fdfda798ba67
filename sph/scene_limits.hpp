#pragma once
// Checks of an SPH scene before the run: gravity strain, fast impacts, bodies in walls or sinks.

#include "materials/material_library.hpp"
#include "particles/sink.hpp"
#include "sph/particle_set.hpp"
#include "sph/scene_places.hpp"
#include "sph/source.hpp"
#include "sph/wall.hpp"

#include <string>
#include <vector>

namespace grainload::sph {

/// Above this strain under its own weight a scene leaves what its models describe: the elastic
/// constants are small-strain (hypoelastic) moduli, and the contact potential, whose stiffness
/// acts like a modulus across a contact (thesis eq. 5.3.12), lets particles sink a tenth of a
/// spacing into a wall per unit strain. Measured on the 2D column collapse at 10 mm: at a
/// gravity strain of 0.025 the final height stays within 2.5 % of the full-stiffness run, at
/// 0.25 it is 18 % lower, at 3.4 the column flows through its floor.
constexpr double kLargestGravityStrain = 0.1;

/// The largest strains gravity imposes on the bodies at rest: rho g H of the tallest column of a
/// body (its extent along gravity plus a spacing) against its material's P-wave modulus
/// K + 4G/3 (as scaled by stiffness_scale) and against the contact stiffness.
struct GravityStrain {
    double strain = 0.0;    ///< against the P-wave modulus
    int material_body = -1; ///< the body where the material strain is largest
    int material = -1;      ///< its material
    double contact = 0.0;
    int contact_body = -1;
    double stress = 0.0;         ///< rho g H of the material_body [Pa]
    double contact_stress = 0.0; ///< rho g H of the contact_body [Pa]
};

/// Over the material particles of `particles` (wall particles skipped); `contact_stiffness` 0
/// when the scene has no contact potential.
GravityStrain gravity_strain(const ParticleSet& particles,
                             const materials::MaterialLibrary& materials, const Vec3& gravity,
                             double spacing, double contact_stiffness);

/// Refuses a scene beyond kLargestGravityStrain: the error names the body, the strain and the
/// modulus or contact stiffness it would need, at the material's `stiffness_scale` (or modulus)
/// key or at [sph.contact] `stiffness`.
void check_gravity_strain(const ScenePlaces& places, const ParticleSet& particles,
                          const materials::MaterialLibrary& materials,
                          const std::vector<std::string>& body_names, const Vec3& gravity,
                          double spacing, double contact_stiffness);

/// A warning ("" when none) for a body launched so fast that the contact potential cannot stop
/// it: the kinetic energy per volume of a particle, rho v^2 / 2, against what the potential of
/// its wall neighbours stores at full overlap, of order the contact stiffness K_c (thesis eq.
/// 5.3.12: U = K_c V_i V_j W(dp) u^n / n summed over the pairs). Above rho v^2 = K_c particles
/// can pass a rigid wall (measured: the 2D column at 100 m/s onto its floor, rho v^2 = 20 MPa
/// against 5.84 MPa, ends below it with an 18 % energy error); a compliant wall that yields
/// may still hold them, so this warns rather than refuses.
std::string impact_warning(const ParticleSet& particles, const std::vector<std::string>& body_names,
                           double contact_stiffness);

/// A point starts inside a wall when it lies nearer to a wall particle than this fraction of the
/// half-sum of the two spacings: the cells the two particles stand for overlap by a tenth of
/// their widths, where particles that touch a wall (their cells sharing a face) are at the full
/// half-sum. A point anywhere inside a lattice of wall layers is at most sqrt(3)/2 of the wall's
/// spacing from a wall particle, within the bound for a body as fine as the wall.
constexpr double kInsideWall = 0.9;

/// Refuses a body whose particles, or a source whose sites, start inside the particles of a wall
/// that acts on its body (Wall::bodies): the contact potential throws such particles off at the
/// first step (measured: a body drawn 30 mm into a box wall of 10 mm particles stopped as
/// unstable at 0.02 s; a source box drawn across the walls at 0.08 s). The error is at the
/// body's shape (its `min`, `file` or `type`) or the source's `min` or shape, names the wall and
/// says how many particles are inside. `support_radius` is the kernel's.
void check_wall_overlaps(const ScenePlaces& places, const ParticleSet& particles,
                         const std::vector<Wall>& walls, const SourceSet& sources,
                         const std::vector<std::string>& body_names, double spacing, int dimension,
                         double support_radius);

/// Sinks that hold a whole body at t = 0 (every particle inside a sink that takes its body, and
/// no source of the body making a particle outside them): the body leaves in the first step.
/// When nothing is left then (every body so held), the scene is refused at the first sink's
/// `normal` (a plane: the side it points to leaves) or `min` (a box); otherwise each held body
/// is a warning, returned.
std::vector<std::string> check_sinks_hold_bodies(const ScenePlaces& places,
                                                 const ParticleSet& particles,
                                                 const particles::SinkSet& sinks,
                                                 const SourceSet& sources,
                                                 const std::vector<std::string>& body_names);

} // namespace grainload::sph
