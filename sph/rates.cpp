#include "sph/rates.hpp"

#include "sph/contact_force.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace grainload::sph {

Mat3 stress_tensor(const Voigt6& s) {
    Mat3 t;
    t << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
    return t;
}

Voigt6 stress_voigt(const Mat3& t) {
    Voigt6 s;
    s << t(0, 0), t(1, 1), t(2, 2), 0.5 * (t(0, 1) + t(1, 0)), 0.5 * (t(1, 2) + t(2, 1)),
        0.5 * (t(2, 0) + t(0, 2));
    return s;
}

namespace {

/// Pairs that exchange stress (same body, neither a wall particle).
inline bool same_continuum(const ParticleSet& p, Index i, Index j) {
    return p.body_id[i] == p.body_id[j] && p.wall_id[i] < 0 && p.wall_id[j] < 0;
}

} // namespace

// Randles & Libersky (1996): M^-1 makes L M^-1 exact for linear fields. In plane strain M
// has no z row or column; its zz entry is set to 1 so that the inverse exists and z stays
// untouched.
//
// M -> I in the interior, and its smallest singular value s is about 0.5 at a flat free
// surface and 0.27 (2D) / 0.21 (3D) at a lattice corner. A particle whose neighbours are nearly
// collinear (a thinning flow front) has s -> 0 while det M can still be well above any fixed
// threshold; M^-1 then multiplies the velocity gradient by 1/s and the continuity equation can
// drive the density negative in one step. So the correction is blended to the plain gradient
// by s: full for s >= 0.15 (every lattice configuration), none for s <= 0.05, linear between.
Mat3 correction_inverse(Mat3 moment, int dimension) {
    if (dimension == 2) {
        moment(2, 2) = 1.0;
    }
    constexpr double full = 0.15;
    constexpr double none = 0.05;
    Eigen::SelfAdjointEigenSolver<Mat3> eigen;
    eigen.computeDirect(moment.transpose() * moment, Eigen::EigenvaluesOnly);
    const double smallest = std::sqrt(std::max(eigen.eigenvalues()(0), 0.0));
    if (!(smallest > none)) {
        return Mat3::Identity();
    }
    const Mat3 inverse = moment.inverse();
    if (smallest >= full) {
        return inverse;
    }
    const double weight = (smallest - none) / (full - none);
    return weight * inverse + (1.0 - weight) * Mat3::Identity();
}

void store_kinematics(ParticleSet& p, Index i, const Mat3& l) {
    p.density_rate[i] = -p.density[i] * l.trace();
    const Mat3 d = 0.5 * (l + l.transpose());
    p.strain_rate[i] << d(0, 0), d(1, 1), d(2, 2), 2.0 * d(0, 1), 2.0 * d(1, 2), 2.0 * d(2, 0);
    const Mat3 w = 0.5 * (l - l.transpose());
    p.spin[i] = Vec3(w(2, 1), w(0, 2), w(1, 0));
}

void compute_velocity_gradient(ParticleSet& p, const NeighbourList& neighbours,
                               const SmoothingKernel& kernel, bool gradient_correction,
                               std::vector<Mat3>& velocity_gradient,
                               std::vector<Mat3>& correction) {
    const Index n = p.size();
    velocity_gradient.resize(static_cast<std::size_t>(n));
    if (gradient_correction) {
        correction.assign(static_cast<std::size_t>(n), Mat3::Identity());
    } else {
        correction.clear();
    }
    const double support_squared = kernel.support_radius() * kernel.support_radius();
#pragma omp parallel for schedule(dynamic, 128)
    for (Index i = 0; i < n; ++i) {
        Mat3 l = Mat3::Zero();
        if (p.wall_id[i] >= 0) {
            velocity_gradient[i] = l;
            continue;
        }
        Mat3 moment = Mat3::Zero();
        const Vec3 xi = p.position[i];
        const Vec3 vi = p.velocity[i];
        for (const Index j : neighbours.neighbours(i)) {
            const Vec3 x_ij = xi - p.position[j];
            const double r2 = x_ij.squaredNorm();
            if (r2 >= support_squared || r2 == 0.0 || !same_continuum(p, i, j)) {
                continue;
            }
            const double r = std::sqrt(r2);
            const Vec3 grad = kernel.gradient(x_ij, r);
            l.noalias() += (p.mass[j] * (p.velocity[j] - vi)) * grad.transpose();
            if (gradient_correction) {
                moment.noalias() += (-p.mass[j] * x_ij) * grad.transpose();
            }
        }
        l /= p.density[i];
        if (gradient_correction) {
            const Mat3 inverse = correction_inverse(moment / p.density[i], kernel.dimension());
            l = l * inverse;
            correction[i] = inverse.transpose();
        }
        velocity_gradient[i] = l;
        store_kinematics(p, i, l);
    }
}

void prepare_force_inputs(const ParticleSet& p, const ArtificialStress& artificial,
                          ForceInputs& inputs) {
    const Index n = p.size();
    inputs.stress_over_rho2.resize(static_cast<std::size_t>(n));
    inputs.artificial_stress.resize(static_cast<std::size_t>(n));
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        const double inv_rho2 = 1.0 / (p.density[i] * p.density[i]);
        const Mat3 sigma = stress_tensor(p.stress[i]);
        // With the correction the momentum equation needs sigma_i/rho_i^2 C_i: formed once here
        // rather than per pair.
        inputs.stress_over_rho2[i] = inputs.gradient_correction.empty()
                                         ? Mat3(sigma * inv_rho2)
                                         : Mat3(sigma * inv_rho2 * inputs.gradient_correction[i]);
        Mat3 r = Mat3::Zero();
        if (artificial.epsilon > 0.0 && p.wall_id[i] < 0) {
            // Gray, Monaghan & Swift (2001) eq. (4.7): only tensile principal stresses.
            Eigen::SelfAdjointEigenSolver<Mat3> eigen;
            eigen.computeDirect(sigma);
            const Vec3 principal = eigen.eigenvalues();
            Vec3 scaled = Vec3::Zero();
            for (int a = 0; a < 3; ++a) {
                scaled[a] =
                    principal[a] > 0.0 ? -artificial.epsilon * principal[a] * inv_rho2 : 0.0;
            }
            r = eigen.eigenvectors() * scaled.asDiagonal() * eigen.eigenvectors().transpose();
        }
        inputs.artificial_stress[i] = r;
    }
}

void compute_accelerations(ParticleSet& p, const NeighbourList& neighbours,
                           const SmoothingKernel& kernel, const SphOptions& options,
                           const ForceInputs& in, std::vector<double>& heating_rate) {
    const Index n = p.size();
    heating_rate.assign(static_cast<std::size_t>(n), 0.0);
    const double support_squared = kernel.support_radius() * kernel.support_radius();
    const double h = kernel.smoothing_length();
    const double w_reference = kernel.value(options.particle_spacing);
    const bool stress_pairs = options.formulation == Formulation::updated_lagrangian;
    const bool use_artificial_stress = stress_pairs && options.artificial_stress.epsilon > 0.0;
    const bool use_viscosity = options.viscosity.alpha > 0.0 || options.viscosity.beta > 0.0;
    const bool use_contact = options.contact.stiffness > 0.0;
    // Whether same-body pairs of the current neighbour list exchange anything here.
    const bool current_pairs_act = stress_pairs || use_viscosity;
    const double alpha = options.viscosity.alpha;
    const double beta = options.viscosity.beta;
    // Monaghan's alpha c h is a viscosity set by the elastic wave speed; a case that scales the
    // moduli down for speed can pin c here (docs/validation/column_collapse_2d.md).
    const double viscosity_speed = options.viscosity.sound_speed;
#pragma omp parallel for schedule(dynamic, 128)
    for (Index i = 0; i < n; ++i) {
        const bool wall = p.wall_id[i] >= 0;
        Vec3 a = wall ? Vec3::Zero() : options.gravity;
        double heating = 0.0;
        const Vec3 xi = p.position[i];
        const Vec3 vi = p.velocity[i];
        const double volume_i = p.mass[i] / p.density[i];
        for (const Index j : neighbours.neighbours(i)) {
            const Vec3 x_ij = xi - p.position[j];
            const double r2 = x_ij.squaredNorm();
            const bool same = same_continuum(p, i, j);
            if (r2 >= support_squared || r2 == 0.0 || (same && !current_pairs_act)) {
                continue;
            }
            const double r = std::sqrt(r2);
            const Vec3 grad = kernel.gradient(x_ij, r);
            if (same) {
                // Total-Lagrangian stress forces come from TotalLagrangian over the reference
                // pairs; the viscosity below still acts between current neighbours.
                Mat3 t = stress_pairs ? Mat3(in.stress_over_rho2[i] + in.stress_over_rho2[j])
                                      : Mat3::Zero();
                if (use_artificial_stress) {
                    const double f = kernel.value(r) / w_reference;
                    t += std::pow(f, options.artificial_stress.exponent) *
                         (in.artificial_stress[i] + in.artificial_stress[j]);
                }
                const Vec3 v_ij = vi - p.velocity[j];
                const double approach = v_ij.dot(x_ij);
                if (use_viscosity && approach < 0.0) {
                    const double mu = h * approach / (r2 + 0.01 * h * h);
                    const double c = viscosity_speed > 0.0
                                         ? viscosity_speed
                                         : 0.5 * (in.sound_speed[i] + in.sound_speed[j]);
                    const double rho = 0.5 * (p.density[i] + p.density[j]);
                    const double pi_ij = (-alpha * c * mu + beta * mu * mu) / rho;
                    t.diagonal().array() -= pi_ij;
                    heating += 0.5 * p.mass[j] * pi_ij * v_ij.dot(grad);
                }
                a.noalias() += p.mass[j] * (t * grad);
            } else if (use_contact && p.body_id[i] != p.body_id[j]) {
                const double volumes = volume_i * p.mass[j] / p.density[j];
                if (wall || p.wall_id[j] >= 0) {
                    // Undamped here: WallContact damps along the wall normal.
                    const double repulsion =
                        contact_repulsion(kernel, options.contact, w_reference, volumes, r);
                    a.noalias() += (repulsion / (r * p.mass[i])) * x_ij;
                } else {
                    const ContactPair pair{x_ij, r, vi - p.velocity[j], volumes,
                                           p.mass[i] * p.mass[j] / (p.mass[i] + p.mass[j])};
                    double dissipation = 0.0;
                    a.noalias() += contact_pair_force(kernel, options.contact, w_reference, pair,
                                                      dissipation) /
                                   p.mass[i];
                    heating += 0.5 * dissipation / p.mass[i];
                }
            }
        }
        p.acceleration[i] = a;
        heating_rate[i] = heating;
    }
}

} // namespace grainload::sph
