#pragma once
// Drucker-Prager cones fitted to the Mohr-Coulomb hexagon of friction angle and cohesion.

#include <string_view>

namespace grainload::materials {

/// How a Drucker-Prager cone is fitted to the Mohr-Coulomb hexagon of (phi, c).
enum class ConeFit {
    plane_strain, ///< same collapse load as Mohr-Coulomb in plane strain (associated flow)
    compression,  ///< through the compressive meridians (outer cone)
    extension,    ///< through the extension meridians
    inner,        ///< inscribed: touches the sides of the hexagon
};

/// Drucker-Prager constants of f = sqrt(J2) + alpha I1 - k and g = sqrt(J2) + alpha_flow I1
/// (tension positive I1).
struct ConeConstants {
    double alpha = 0.0;
    double k = 0.0;
    double alpha_flow = 0.0;
};

/// Formulas and their derivation in docs/theory/materials.md (after de Souza Neto, Peric &
/// Owen, "Computational Methods for Plasticity" (2008), eqs. 6.121-6.123, rewritten from
/// p = I1/3 to I1; the plane-strain fit generalised to psi != phi). Angles in radians,
/// cohesion in Pa.
ConeConstants fit_cone(ConeFit fit, double friction_angle, double cohesion, double dilatancy_angle);

/// Parse "plane_strain" | "compression" | "extension" | "inner".
ConeFit cone_fit_from_name(std::string_view name);

} // namespace grainload::materials
