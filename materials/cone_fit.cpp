#include "materials/cone_fit.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace grainload::materials {

namespace {

/// alpha and k of a cone through one meridian family: 6 sin / (sqrt3 (3 -/+ sin)) in p form
/// (de Souza Neto eqs. 6.121, 6.122), i.e. 2 sin / (sqrt3 (3 -/+ sin)) on I1.
ConeConstants meridian_cone(double phi, double c, double psi, double sign) {
    const double sqrt3 = std::sqrt(3.0);
    const auto coefficient = [&](double angle) {
        return 2.0 * std::sin(angle) / (sqrt3 * (3.0 + sign * std::sin(angle)));
    };
    return {coefficient(phi), 6.0 * c * std::cos(phi) / (sqrt3 * (3.0 + sign * std::sin(phi))),
            coefficient(psi)};
}

/// Plane strain: with eps_zz^p = 0 the DP limit state reduces in the plane to
/// tau (1 - 3 alpha af) / sqrt(1 - 3 af^2) = k - 3 alpha sigma_m; equating it with Mohr-Coulomb
/// tau = c cos(phi) - sigma_m sin(phi), and the plastic dilatancy ratio with sin(psi), gives
/// af = tan(psi) / sqrt(9 + 12 tan^2 psi), alpha = sin(phi) / (3 (sqrt(1 - 3 af^2) +
/// af sin(phi))), k = c cos(phi) (1 - 3 alpha af) / sqrt(1 - 3 af^2). For psi = phi this is
/// de Souza Neto eq. 6.123; for psi = 0 it gives alpha = sin(phi) / 3, k = c cos(phi).
ConeConstants plane_strain_cone(double phi, double c, double psi) {
    const double tan_psi = std::tan(psi);
    const double af = tan_psi / std::sqrt(9.0 + 12.0 * tan_psi * tan_psi);
    const double root = std::sqrt(1.0 - 3.0 * af * af);
    const double alpha = std::sin(phi) / (3.0 * (root + af * std::sin(phi)));
    return {alpha, c * std::cos(phi) * (1.0 - 3.0 * alpha * af) / root, af};
}

/// Inscribed cone (tangent to the hexagon's sides): sin / (sqrt3 sqrt(3 + sin^2)) on I1.
ConeConstants inscribed_cone(double phi, double c, double psi) {
    const auto coefficient = [](double angle) {
        return std::sin(angle) /
               (std::sqrt(3.0) * std::sqrt(3.0 + std::sin(angle) * std::sin(angle)));
    };
    const double k =
        std::sqrt(3.0) * c * std::cos(phi) / std::sqrt(3.0 + std::sin(phi) * std::sin(phi));
    return {coefficient(phi), k, coefficient(psi)};
}

} // namespace

ConeConstants fit_cone(ConeFit fit, double friction_angle, double cohesion,
                       double dilatancy_angle) {
    switch (fit) {
    case ConeFit::plane_strain:
        return plane_strain_cone(friction_angle, cohesion, dilatancy_angle);
    case ConeFit::compression:
        return meridian_cone(friction_angle, cohesion, dilatancy_angle, -1.0);
    case ConeFit::extension:
        return meridian_cone(friction_angle, cohesion, dilatancy_angle, 1.0);
    case ConeFit::inner:
        return inscribed_cone(friction_angle, cohesion, dilatancy_angle);
    }
    throw std::invalid_argument("fit_cone: unknown cone fit");
}

ConeFit cone_fit_from_name(std::string_view name) {
    if (name == "plane_strain") {
        return ConeFit::plane_strain;
    }
    if (name == "compression") {
        return ConeFit::compression;
    }
    if (name == "extension") {
        return ConeFit::extension;
    }
    if (name == "inner") {
        return ConeFit::inner;
    }
    throw std::invalid_argument("unknown cone fit '" + std::string(name) + "'");
}

} // namespace grainload::materials
