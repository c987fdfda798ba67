#pragma once
// The kinematic and force passes of SPH: velocity gradient and rates, then accelerations.

#include "particles/neighbour_list.hpp"
#include "sph/kernels.hpp"
#include "sph/pair_lanes.hpp"
#include "sph/pair_parts.hpp"
#include "sph/particle_set.hpp"
#include "sph/sph_options.hpp"

#include <span>
#include <vector>

namespace grainload::sph {

/// Conversions between Voigt6 stress (tensor shear, order xx yy zz xy yz zx) and 3x3 tensors.
/// Inline: the stress update calls them for every particle and step, and their results passed
/// through the stack were stored in 8-byte pieces and read back in 16-byte ones.
inline Mat3 stress_tensor(const Voigt6& s) {
    Mat3 t;
    t << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
    return t;
}

inline Voigt6 stress_voigt(const Mat3& t) {
    Voigt6 s;
    s << t(0, 0), t(1, 1), t(2, 2), 0.5 * (t(0, 1) + t(1, 0)), 0.5 * (t(1, 2) + t(2, 1)),
        0.5 * (t(2, 0) + t(0, 2));
    return s;
}

/// M^-1 of the Randles-Libersky corrected gradient, blended to I where M is near singular
/// (smallest singular value below 0.15; none below 0.05). Plane strain: M's zz entry is set to 1.
Mat3 correction_inverse(Mat3 moment, int dimension);

/// From the velocity gradient L of particle i: density_rate = -rho tr L, strain_rate = sym L
/// (engineering shear), spin = axial vector of skew L.
void store_kinematics(ParticleSet& particles, Index i, const Mat3& velocity_gradient);

/// How the pair passes do their same-body pairs' arithmetic. The production form (cubic spline,
/// no gradient correction; the forces also without artificial stress, 3D or plane strain; the
/// kinematic pass in 3D) goes to the vector units where the processor has AVX2
/// (pair_lanes.hpp), with the same bits as the scalar rows;
/// `scalar` keeps the scalar rows everywhere (the reference the tests and benches compare
/// against).
enum class PairArithmetic { lanes_where_available, scalar };

/// Kinematic pass over pairs of the same body: velocity gradient
/// L_i = sum_j (m_j / rho_i) (v_j - v_i) (grad_i W_ij)^T, the velocity-difference form of
/// thesis eqs. 4.6.1.13 and 4.6.1.17 with the weight m_j/rho_i instead of m_j/rho_j, which
/// makes the stress power exactly the work of the momentum equation (and rho_i tr L the
/// standard continuity sum). With `gradient_correction`, L_i is multiplied by M_i^-1,
/// M_i = sum_j (m_j / rho_i) (x_j - x_i) (grad_i W_ij)^T (Randles & Libersky 1996; Bonet &
/// Lok 1999), exact for linear fields, and C_i = M_i^-T is stored in `correction` for the
/// momentum equation; otherwise `correction` is cleared. From L it sets, per material
/// particle: density_rate = -rho tr L (continuity with velocity differences, eq. 4.5.3.13),
/// strain_rate = sym L in engineering shear (eq. 4.6.1.13), spin = axial vector of skew L
/// (eq. 4.6.1.17). The thesis writes these with the gradient taken at x_j; the signs here are
/// those of grad_i W_ij = W'(r) x_ij / r.
/// With `entry_factor` it also stores W'(r)/r of every same-body neighbour entry inside the
/// support (indexed like the list's entries; other entries are left as they were), for the
/// force pass at the same positions.
/// Each same-body pair is taken once, from the row of its lower index (sph/pair_parts.hpp): the
/// list may hold it in both rows (the other is skipped) or, as the solver's does
/// (NeighbourList::halve_pairs), in that row only. `scratch` holds the sums of the threads after
/// the first between calls (nullptr: allocated per call). With `records` (and no
/// `entry_factor`), where the pairs run in vector lanes (the 3D cubic spline without correction,
/// on AVX2), the pass writes each material particle's position, velocity and mass into its
/// record (ForceInputs::pair_records, which prepare_force_inputs then completes) and reads the
/// neighbours' from there; otherwise the scalar rows run. Same bits either way.
void compute_velocity_gradient(ParticleSet& particles, const particles::NeighbourList& neighbours,
                               const SmoothingKernel& kernel, bool gradient_correction,
                               std::vector<Mat3>& velocity_gradient, std::vector<Mat3>& correction,
                               std::vector<double>* entry_factor = nullptr,
                               PairScratch* scratch = nullptr,
                               PairArithmetic arithmetic = PairArithmetic::lanes_where_available,
                               std::vector<PairRecord>* records = nullptr);

/// Per-particle quantities the force pass reads, computed once per step.
struct ForceInputs {
    /// sigma_i / rho_i^2 C_i with the gradient correction (material particles; wall entries
    /// unused); empty without it.
    std::vector<Mat3> stress_over_rho2;
    /// Without the gradient correction: sigma_i / rho_i^2, symmetric, as its six entries xx, yy,
    /// zz, xy, xz, yz, with the particle's mass, density, position, velocity and c
    /// (pair_lanes.hpp), so that the force pass loads a neighbour's data as blocks (material
    /// particles; wall entries unused); empty with the correction.
    std::vector<PairRecord> pair_records;
    std::vector<Mat3> artificial_stress; ///< R_i of material particles; empty when epsilon = 0
    /// c_i of the artificial viscosity: the P-wave speed of the particle's material before its
    /// stiffness_scale (materials/elastic_constants.hpp), so that alpha c does not follow it.
    std::vector<double> sound_speed;
    /// C_i = M_i^-T of compute_velocity_gradient; empty without the gradient correction.
    std::vector<Mat3> gradient_correction;
    /// W'(r)/r per neighbour entry from compute_velocity_gradient at the current positions and
    /// list, which the force pass then reads instead of evaluating the kernel again; empty: it
    /// evaluates the kernel. Same values either way.
    std::vector<double> entry_factor;
};

/// Fill stress_over_rho2 or pair_records, and artificial_stress, from the particles' current
/// state (after compute_velocity_gradient has set gradient_correction, and again whenever
/// positions, velocities, densities or stresses change before the force pass).
void prepare_force_inputs(const ParticleSet& particles, const ArtificialStress& artificial,
                          ForceInputs& inputs);

/// Whether compute_accelerations does the same-body pairs in vector lanes (pair_lanes.hpp): the
/// cubic spline with stress and viscosity, without artificial stress or gradient correction
/// (the production form, 3D or plane strain), on a processor with AVX2, unless `arithmetic`
/// asks for the scalar rows. Its kernel gradients then need not be stored by the kinematic pass.
bool force_pass_uses_lanes(const SmoothingKernel& kernel, const SphOptions& options,
                           PairArithmetic arithmetic = PairArithmetic::lanes_where_available);

/// Dynamic pass: acceleration of every particle and the viscous heating rate.
/// Same-body pairs: momentum, thesis eq. (4.5.4.13) for tension-positive stress,
///   dv_i/dt = sum_j m_j (sigma_i/rho_i^2 + sigma_j/rho_j^2 + f^n (R_i + R_j) - Pi_ij I) grad_i
///   W_ij
/// and with the gradient correction sigma_i/rho_i^2 C_i + sigma_j/rho_j^2 C_j in place of the
/// first two terms (Bonet & Lok 1999): linear and angular momentum are then both conserved.
///   plus gravity; heating de_i/dt += 1/2 sum_j m_j Pi_ij v_ij . grad_i W_ij (Monaghan 1992).
/// Pairs of different bodies (walls included): the contact potential, thesis eq. (5.3.12).
/// Wall particles get only contact; their `acceleration` times mass is the force on the wall.
/// With Formulation::total_lagrangian the same-body stress terms are left out (TotalLagrangian
/// adds them); viscosity and contact stay.
/// Same-body pairs once each, as compute_velocity_gradient takes them (the pair's force on j is
/// minus its force on i: momentum is conserved pair by pair); contact pairs from both rows.
/// `arithmetic` as for compute_velocity_gradient; where force_pass_uses_lanes, the lanes
/// evaluate W'(r)/r themselves and `inputs.entry_factor` is not read.
/// `contact_heating_rate`, when given, receives the part of each particle's heating rate that
/// the dashpot between bodies put there (its share of the pair's dissipation); heating_rate
/// less it is the artificial viscosity's heating (the energy books' split of the dissipation).
void compute_accelerations(ParticleSet& particles, const particles::NeighbourList& neighbours,
                           const SmoothingKernel& kernel, const SphOptions& options,
                           const ForceInputs& inputs, std::vector<double>& heating_rate,
                           PairScratch* scratch = nullptr,
                           PairArithmetic arithmetic = PairArithmetic::lanes_where_available,
                           std::vector<double>* contact_heating_rate = nullptr);

} // namespace grainload::sph
