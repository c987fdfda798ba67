#pragma once

#include "materials/material_library.hpp"
#include "sph/particle_set.hpp"

#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

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
void check_gravity_strain(const io::CaseTable& root, const ParticleSet& particles,
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

} // namespace grainload::sph
