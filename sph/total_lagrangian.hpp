#pragma once
// Total-Lagrangian SPH for solid bodies: kernel sums over the reference configuration.

#include "sph/kernels.hpp"
#include "sph/particle_set.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace grainload::sph {

/// Total-Lagrangian SPH for solid bodies (Bonet & Kulasegaram 2000; Vidal, Bonet & Huerta
/// 2007): kernel sums run over the reference (initial) configuration X, with the neighbours,
/// volumes V0 = m / rho0 and corrected kernel gradients fixed at the start. Pairs never change,
/// so the tensile instability of the updated-Lagrangian kernel does not arise and no artificial
/// stress is needed; the body must keep its neighbours (elastic and moderately plastic solids,
/// not flowing sand).
///
/// Kinematics, with the corrected reference gradient g_ij = C_i grad0 W_ij, C_i = M_i^-T,
/// M_i = sum_j V0_j (X_j - X_i) (grad0 W_ij)^T (Randles & Libersky 1996):
///   F_i = I + sum_j V0_j (u_j - u_i) g_ij^T,  u = x - X (exact for linear displacement fields),
///   dF_i/dt = sum_j V0_j (v_j - v_i) g_ij^T,  L_i = dF_i/dt F_i^-1,  rho_i = rho0_i / det F_i.
/// The material's stress update is unchanged (Jaumann rate of L). Momentum, the discrete
/// derivative of sum_i V0_i Psi(F_i) (Bonet & Lok 1999), with P = J sigma F^-T:
///   m_i dv_i/dt = sum_j V0_i V0_j (P_i C_i + P_j C_j) grad0 W_ij,
/// antisymmetric in i, j, so linear momentum is conserved to round-off.
class TotalLagrangian {
  public:
    /// The reference configuration is `particles` as given: pairs of the same body (no wall
    /// particles) within the kernel support.
    TotalLagrangian(const ParticleSet& particles, const SmoothingKernel& kernel);

    /// Sets density, density_rate, strain_rate and spin of every material particle and returns
    /// L in `velocity_gradient` (wall particles: zero).
    void compute_kinematics(ParticleSet& particles, std::vector<Mat3>& velocity_gradient);
    /// Adds the stress forces of the momentum equation above to the particles' accelerations
    /// (after compute_kinematics for the current positions).
    void add_stress_forces(ParticleSet& particles);

    const std::vector<Mat3>& deformation_gradient() const { return deformation_gradient_; }
    std::size_t bytes() const;

  private:
    Vec3 reference_gradient(Index i, Index j, Index pair) const {
        return gradient_factor_[pair] * (reference_position_[i] - reference_position_[j]);
    }

    int dimension_;
    std::vector<Index> offset_;
    std::vector<std::int32_t> neighbour_;
    /// W'(R)/R of each stored pair: grad0 W_ij = W'(R)/R (X_i - X_j), formed when needed, which
    /// keeps 8 bytes per pair entry instead of 24.
    std::vector<double> gradient_factor_;
    std::vector<Vec3> reference_position_;
    std::vector<double> reference_density_;
    std::vector<Mat3> correction_; ///< C_i
    std::vector<Mat3> deformation_gradient_;
    std::vector<Mat3> piola_correction_; ///< P_i C_i, formed once per force evaluation
};

} // namespace grainload::sph
