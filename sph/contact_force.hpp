#pragma once
// The contact potential between particles of different bodies and walls: force, energy, stiffness.

#include "sph/kernels.hpp"
#include "sph/sph_options.hpp"

#include <algorithm>
#include <cmath>

namespace grainload::sph {

/// One pair of particles of different bodies (or a body and a wall) in contact.
struct ContactPair {
    Vec3 x_ij;           ///< x_i - x_j
    double r;            ///< |x_ij| > 0
    Vec3 v_ij;           ///< v_i - v_j
    double volumes;      ///< V_i V_j
    double reduced_mass; ///< m_i m_j / (m_i + m_j)
};

/// Repulsion of the contact potential at distance r, thesis eq. (5.3.12):
///   F(r) = -K V_i V_j (W(r)/W(dp))^(n-1) W'(r) >= 0, along x_ij.
inline double contact_repulsion(const SmoothingKernel& kernel, const ContactPotential& contact,
                                double w_reference, double volumes, double r) {
    return -contact.stiffness * volumes *
           std::pow(kernel.value(r) / w_reference, contact.exponent - 1.0) *
           kernel.radial_derivative(r);
}

/// Energy stored in the contact potential of one pair at distance r: the work of
/// contact_repulsion from r out to the support radius, where W = 0. With u = W(r)/W(dp),
/// F dr = -K V_i V_j u^(n-1) W'(r) dr = -K V_i V_j W(dp) u^(n-1) du, so
///   U(r) = K V_i V_j W(dp) u^n / n   (volumes held fixed).
inline double contact_energy(const SmoothingKernel& kernel, const ContactPotential& contact,
                             double w_reference, double volumes, double r) {
    const double u = kernel.value(r) / w_reference;
    return contact.stiffness * volumes * w_reference * std::pow(u, contact.exponent) /
           contact.exponent;
}

/// Linearised stiffness |dF/dr| of the contact potential at r, by central difference.
inline double contact_stiffness(const SmoothingKernel& kernel, const ContactPotential& contact,
                                double w_reference, double volumes, double r) {
    const double delta = 1e-4 * kernel.smoothing_length();
    const double r_minus = std::max(r - delta, 0.5 * r);
    const double r_plus = r + delta;
    return std::abs(contact_repulsion(kernel, contact, w_reference, volumes, r_minus) -
                    contact_repulsion(kernel, contact, w_reference, volumes, r_plus)) /
           (r_plus - r_minus);
}

/// Force of j on i for two particles of different bodies: the contact-potential repulsion
/// plus a normal viscous damper at the ratio zeta of the pair's critical damping,
/// 2 zeta sqrt(k m) with k = |dF/dr| and m the reduced mass (the dashpot of the
/// Cundall-Strack contact, which the thesis' potential lacks: without it two bodies that
/// meet bounce on the contact layer for ever). The normal force is never attractive.
/// `dissipation` receives the power the damper takes out (>= 0). Wall pairs are damped per
/// particle along the wall normal instead (wall_contact.hpp): a pair damper along x_ij would
/// also resist sliding past the wall's particles, a spurious friction.
inline Vec3 contact_pair_force(const SmoothingKernel& kernel, const ContactPotential& contact,
                               double w_reference, const ContactPair& pair, double& dissipation) {
    const Vec3 e = pair.x_ij / pair.r;
    const double repulsion = contact_repulsion(kernel, contact, w_reference, pair.volumes, pair.r);
    dissipation = 0.0;
    if (!(contact.damping_ratio > 0.0)) {
        return repulsion * e;
    }
    const double stiffness = contact_stiffness(kernel, contact, w_reference, pair.volumes, pair.r);
    const double normal_speed = pair.v_ij.dot(e);
    const double damper =
        -2.0 * contact.damping_ratio * std::sqrt(stiffness * pair.reduced_mass) * normal_speed;
    const double normal = std::max(repulsion + damper, 0.0);
    dissipation = -(normal - repulsion) * normal_speed;
    return normal * e;
}

} // namespace grainload::sph
