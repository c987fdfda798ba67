#pragma once
// The stress update of SPH particles: the Jaumann rotation, then each particle's material.

#include "materials/material.hpp"
#include "sph/particle_set.hpp"

#include <span>
#include <vector>

namespace grainload::sph {

/// Incremental rotation of the Jaumann rate (thesis eq. 4.6.1.8) over one step, after Hughes &
/// Winget (1980): Q = (I - dt/2 W)^-1 (I + dt/2 W), W the spin tensor of the axial vector
/// `spin`. Q is exactly orthogonal, so sigma' = Q sigma Q^T keeps the stress invariants to
/// round-off however large the rotation per step; to second order it is the Jaumann update
/// sigma + dt (W sigma - sigma W). Inline, as stress_tensor.
inline Mat3 jaumann_rotation(const Vec3& spin, double dt) {
    // With S = dt/2 W = skew(a), a = dt/2 spin: S^3 = -|a|^2 S, so (I - S)^-1 = I + (S + S^2) /
    // (1 + |a|^2) and the Cayley transform is Q = I + 2 (S + S^2) / (1 + |a|^2), where
    // S^2 = a a^T - |a|^2 I: no 3x3 inverse each particle-step.
    const Vec3 a = 0.5 * dt * spin;
    const double squared = a.squaredNorm();
    const double scale = 2.0 / (1.0 + squared);
    Mat3 s;
    s << -squared, -a.z(), a.y(), a.z(), -squared, -a.x(), -a.y(), a.x(), -squared;
    s.noalias() += a * a.transpose();
    return Mat3::Identity() + scale * s;
}

/// Per material particle: rotate the stress by jaumann_rotation(), then call the particle's
/// material with strain increment strain_rate * dt (engineering shear) over the step dt (from
/// which a rate-dependent material takes its strain rate), a block of up to 64 consecutive
/// particles of one material at a time (Material::update_points). The specific internal
/// energy advances by the stress power at the mid-step stress, thesis eq. (4.5.5.9) in the
/// form de/dt = sigma : D / rho. Plastic strain and plastic region are stored for output.
/// Only the first `count` particles (< 0: all): mirror images after them (sph/symmetry.hpp)
/// share their sources' material state and are copied from them instead.
/// `plastic_work`, when not empty (one entry per particle), receives each material particle's
/// specific plastic work of the step, J/kg: sigma_mid : (d eps - D_e^-1 d sigma) / rho, the
/// stress power less the change of the elastic strain energy (the energy books' dissipation by
/// plasticity); entries of wall particles are left as they are.
void update_stresses(ParticleSet& particles, std::span<const materials::Material* const> materials,
                     double dt, Index count = -1, std::span<double> plastic_work = {});

} // namespace grainload::sph
