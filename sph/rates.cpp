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

namespace {

/// Which particles exchange stress: key[i] is the body of a material particle and a value no
/// other particle has (-2 - i) for a wall particle, so key[i] == key[j] exactly for the pairs
/// that exchange stress (same body, neither a wall particle): one load per neighbour.
std::vector<int> continuum_keys(const ParticleSet& p) {
    std::vector<int> key(static_cast<std::size_t>(p.size()));
    const Index n = p.size();
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        key[i] = p.wall_id[i] < 0 ? p.body_id[i] : static_cast<int>(-2 - i);
    }
    return key;
}

/// Row i of the velocity-gradient pass in D = 2 or 3 components: plane-strain particles have
/// z = 0, so the z row and column of L and M are exact zeros and are left out. The sums run in
/// the order, and with the operations, of the Eigen expressions they replace.
template <class Shape, int D, bool Corrected> struct GradientRow {
    const ParticleSet& p;
    const NeighbourList& neighbours;
    const ShapeTerms<Shape> w;
    const std::vector<int>& key;
    const double support_squared;
    double* entry_factor; ///< nullptr, or W'(r)/r of each same-body entry in the support

    void operator()(Index i, Mat3& l_out, Mat3& moment_out) const {
        double l[D][D] = {};
        double moment[D][D] = {};
        Mat3 l3 = Mat3::Zero();
        Mat3 moment3 = Mat3::Zero();
        const Vec3 xi = p.position[i];
        const Vec3 vi = p.velocity[i];
        const int key_i = key[i];
        const auto list = neighbours.neighbours(i);
        double* factor_of_entry =
            entry_factor != nullptr ? entry_factor + neighbours.first_entry(i) : nullptr;
        for (std::size_t k = 0; k < list.size(); ++k) {
            const Index j = list[k];
            const Vec3& xj = p.position[j];
            if constexpr (D == 3) {
                // Eigen's vector forms: the same operations, packed two by two.
                const Vec3 x_ij = xi - xj;
                const double r2 = x_ij.squaredNorm();
                if (r2 >= support_squared || r2 == 0.0 || key[j] != key_i) {
                    continue;
                }
                const Vec3 grad = w.gradient_factor(std::sqrt(r2)) * x_ij;
                const double mj = p.mass[j];
                l3.noalias() += (mj * (p.velocity[j] - vi)) * grad.transpose();
                if constexpr (Corrected) {
                    moment3.noalias() += (-mj * x_ij) * grad.transpose();
                }
                continue;
            }
            double d[D];
            for (int c = 0; c < D; ++c) {
                d[c] = xi[c] - xj[c];
            }
            const double r2 = d[0] * d[0] + d[1] * d[1];
            if (r2 >= support_squared || r2 == 0.0 || key[j] != key_i) {
                continue;
            }
            const double f = w.gradient_factor(std::sqrt(r2));
            if (factor_of_entry != nullptr) {
                factor_of_entry[k] = f;
            }
            double g[D];
            for (int c = 0; c < D; ++c) {
                g[c] = f * d[c];
            }
            const double mj = p.mass[j];
            const Vec3& vj = p.velocity[j];
            for (int r = 0; r < D; ++r) {
                const double dv = mj * (vj[r] - vi[r]);
                for (int c = 0; c < D; ++c) {
                    l[r][c] += dv * g[c];
                }
            }
            if constexpr (Corrected) {
                for (int r = 0; r < D; ++r) {
                    const double dx = -mj * d[r];
                    for (int c = 0; c < D; ++c) {
                        moment[r][c] += dx * g[c];
                    }
                }
            }
        }
        if constexpr (D == 3) {
            l_out = l3;
            moment_out = moment3;
            return;
        }
        l_out.setZero();
        moment_out.setZero();
        for (int r = 0; r < D; ++r) {
            for (int c = 0; c < D; ++c) {
                l_out(r, c) = l[r][c];
                moment_out(r, c) = moment[r][c];
            }
        }
    }
};

template <class Shape, int D, bool Corrected>
void velocity_gradient_pass(ParticleSet& p, const NeighbourList& neighbours,
                            const SmoothingKernel& kernel, std::vector<Mat3>& velocity_gradient,
                            std::vector<Mat3>& correction, double* entry_factor) {
    const std::vector<int> key = continuum_keys(p);
    const GradientRow<Shape, D, Corrected> row{p,
                                               neighbours,
                                               ShapeTerms<Shape>(kernel),
                                               key,
                                               kernel.support_radius() * kernel.support_radius(),
                                               entry_factor};
    const Index n = p.size();
#pragma omp parallel for schedule(dynamic, 128)
    for (Index i = 0; i < n; ++i) {
        if (p.wall_id[i] >= 0) {
            velocity_gradient[i].setZero();
            continue;
        }
        Mat3 l;
        Mat3 moment;
        row(i, l, moment);
        l /= p.density[i];
        if constexpr (Corrected) {
            const Mat3 inverse = correction_inverse(moment / p.density[i], kernel.dimension());
            l = l * inverse;
            correction[i] = inverse.transpose();
        }
        velocity_gradient[i] = l;
        store_kinematics(p, i, l);
    }
}

} // namespace

void compute_velocity_gradient(ParticleSet& p, const NeighbourList& neighbours,
                               const SmoothingKernel& kernel, bool gradient_correction,
                               std::vector<Mat3>& velocity_gradient, std::vector<Mat3>& correction,
                               std::vector<double>* entry_factor) {
    const Index n = p.size();
    velocity_gradient.resize(static_cast<std::size_t>(n));
    if (entry_factor != nullptr) {
        entry_factor->resize(static_cast<std::size_t>(neighbours.pair_entries()));
    }
    double* factors = entry_factor != nullptr ? entry_factor->data() : nullptr;
    if (gradient_correction) {
        correction.assign(static_cast<std::size_t>(n), Mat3::Identity());
    } else {
        correction.clear();
    }
    kernel.visit_shape([&](auto shape) {
        using Shape = decltype(shape);
        auto pass = [&](auto dimension, auto corrected) {
            velocity_gradient_pass<Shape, decltype(dimension)::value, decltype(corrected)::value>(
                p, neighbours, kernel, velocity_gradient, correction, factors);
        };
        using Two = std::integral_constant<int, 2>;
        using Three = std::integral_constant<int, 3>;
        if (kernel.dimension() == 2) {
            gradient_correction ? pass(Two{}, std::true_type{}) : pass(Two{}, std::false_type{});
        } else {
            gradient_correction ? pass(Three{}, std::true_type{})
                                : pass(Three{}, std::false_type{});
        }
    });
}

void prepare_force_inputs(const ParticleSet& p, const ArtificialStress& artificial,
                          ForceInputs& inputs) {
    const Index n = p.size();
    inputs.stress_over_rho2.resize(static_cast<std::size_t>(n));
    const bool artificial_on = artificial.epsilon > 0.0;
    if (artificial_on) {
        inputs.artificial_stress.resize(static_cast<std::size_t>(n));
    } else {
        inputs.artificial_stress.clear(); // 72 bytes per particle that nothing reads
    }
    // Wall particles are skipped: the force pass reads these only for pairs of one body
    // (their entries keep whatever they held). Dynamic, as walls and grains alternate in
    // blocks.
#pragma omp parallel for schedule(dynamic, 256)
    for (Index i = 0; i < n; ++i) {
        if (p.wall_id[i] >= 0) {
            continue;
        }
        const double inv_rho2 = 1.0 / (p.density[i] * p.density[i]);
        const Mat3 sigma = stress_tensor(p.stress[i]);
        // With the correction the momentum equation needs sigma_i/rho_i^2 C_i: formed once here
        // rather than per pair.
        inputs.stress_over_rho2[i] = inputs.gradient_correction.empty()
                                         ? Mat3(sigma * inv_rho2)
                                         : Mat3(sigma * inv_rho2 * inputs.gradient_correction[i]);
        if (!artificial_on) {
            continue;
        }
        // Gray, Monaghan & Swift (2001) eq. (4.7): only tensile principal stresses.
        Eigen::SelfAdjointEigenSolver<Mat3> eigen;
        eigen.computeDirect(sigma);
        const Vec3 principal = eigen.eigenvalues();
        Vec3 scaled = Vec3::Zero();
        for (int a = 0; a < 3; ++a) {
            scaled[a] = principal[a] > 0.0 ? -artificial.epsilon * principal[a] * inv_rho2 : 0.0;
        }
        inputs.artificial_stress[i] =
            eigen.eigenvectors() * scaled.asDiagonal() * eigen.eigenvectors().transpose();
    }
}

namespace {

/// Settings of the force pass, read once per call.
struct ForceSettings {
    double support_squared;
    double h;
    double h2_softening; ///< 0.01 h^2 of Monaghan's mu
    double w_reference;
    bool stress_pairs;
    bool use_artificial_stress;
    double artificial_exponent;
    bool use_viscosity;
    bool use_contact;
    bool current_pairs_act; ///< whether same-body pairs of the current list exchange anything
    double alpha;
    double beta;
    double viscosity_speed;
    Vec3 gravity;

    ForceSettings(const SmoothingKernel& kernel, const SphOptions& options)
        : support_squared(kernel.support_radius() * kernel.support_radius()),
          h(kernel.smoothing_length()), h2_softening(0.01 * h * h),
          w_reference(kernel.value(options.particle_spacing)),
          stress_pairs(options.formulation == Formulation::updated_lagrangian),
          use_artificial_stress(stress_pairs && options.artificial_stress.epsilon > 0.0),
          artificial_exponent(options.artificial_stress.exponent),
          use_viscosity(options.viscosity.alpha > 0.0 || options.viscosity.beta > 0.0),
          use_contact(options.contact.stiffness > 0.0),
          current_pairs_act(stress_pairs || use_viscosity), alpha(options.viscosity.alpha),
          beta(options.viscosity.beta), viscosity_speed(options.viscosity.sound_speed),
          gravity(options.gravity) {}
};

/// Row i of the force pass in D = 2 or 3 components (plane strain: the z terms are exact zeros
/// and are left out). Same operations and order as the Eigen expressions of the generic form.
template <class Shape, int D> struct ForceRow {
    const ParticleSet& p;
    const NeighbourList& neighbours;
    const SmoothingKernel& kernel;
    const ShapeTerms<Shape> w;
    const ForceSettings& s;
    const ContactPotential& contact;
    const ForceInputs& in;
    const std::vector<int>& key;
    /// in.entry_factor's data, or nullptr: the kernel is evaluated here.
    const double* entry_factor;

    /// Stress, artificial stress and viscosity of a same-body pair; adds to a and heating.
    /// in_support false: computed as if, added nowhere (a branch-free skip).
    void continuum_pair(Index i, Index j, const double (&d)[D], double r, double r2,
                        const double (&g)[D], bool in_support, double (&a)[3],
                        double& heating) const {
        double t[D][D] = {};
        if (s.stress_pairs) {
            const Mat3& si = in.stress_over_rho2[i];
            const Mat3& sj = in.stress_over_rho2[j];
            for (int row = 0; row < D; ++row) {
                for (int c = 0; c < D; ++c) {
                    t[row][c] = si(row, c) + sj(row, c);
                }
            }
        }
        if (s.use_artificial_stress) {
            const double fn = std::pow(w.value(r) / s.w_reference, s.artificial_exponent);
            const Mat3& ri = in.artificial_stress[i];
            const Mat3& rj = in.artificial_stress[j];
            for (int row = 0; row < D; ++row) {
                for (int c = 0; c < D; ++c) {
                    t[row][c] += fn * (ri(row, c) + rj(row, c));
                }
            }
        }
        const Vec3& vi = p.velocity[i];
        const Vec3& vj = p.velocity[j];
        double v_ij[D];
        double approach = 0.0;
        for (int c = 0; c < D; ++c) {
            v_ij[c] = vi[c] - vj[c];
            approach = c == 0 ? v_ij[0] * d[0] : approach + v_ij[c] * d[c];
        }
        // Branch free: whether the pair approaches is a coin toss per pair, and a mispredicted
        // branch here costs more than the arithmetic it would skip. Subtracting +0 and the
        // selects below leave every value as the branching form had it.
        double pi_ij = 0.0;
        double heat = 0.0;
        if (s.use_viscosity) {
            const double mu = s.h * approach / (r2 + s.h2_softening);
            const double c = s.viscosity_speed > 0.0
                                 ? s.viscosity_speed
                                 : 0.5 * (in.sound_speed[i] + in.sound_speed[j]);
            const double rho = 0.5 * (p.density[i] + p.density[j]);
            const double pi_all = (-s.alpha * c * mu + s.beta * mu * mu) / rho;
            double power = v_ij[0] * g[0];
            for (int k = 1; k < D; ++k) {
                power = power + v_ij[k] * g[k];
            }
            const bool viscous = approach < 0.0;
            pi_ij = viscous ? pi_all : 0.0;
            heat = 0.5 * p.mass[j] * pi_all * power;
            heating = viscous && in_support ? heating + heat : heating;
        }
        for (int k = 0; k < D; ++k) {
            t[k][k] -= pi_ij;
        }
        // m_j (t g) summed as Eigen 3.4 sums it: (m_j t) g, rows x and y left to right, the
        // z row as e0 + (e1 + e2), so that the pass reproduces the generic form bit for bit.
        const double mj = p.mass[j];
        for (int row = 0; row < 2; ++row) {
            double tg = (mj * t[row][0]) * g[0];
            for (int c = 1; c < D; ++c) {
                tg += (mj * t[row][c]) * g[c];
            }
            a[row] = in_support ? a[row] + tg : a[row];
        }
        if constexpr (D == 3) {
            const double tg =
                (mj * t[2][0]) * g[0] + ((mj * t[2][1]) * g[1] + (mj * t[2][2]) * g[2]);
            a[2] = in_support ? a[2] + tg : a[2];
        }
    }

    /// Contact potential (and the dashpot between bodies) of a pair of different bodies.
    void contact_pair(Index i, Index j, const Vec3& x_ij, double r, bool wall, double volume_i,
                      double (&a)[3], double& heating) const {
        const double volumes = volume_i * p.mass[j] / p.density[j];
        Vec3 add;
        if (wall || p.wall_id[j] >= 0) {
            // Undamped here: WallContact damps along the wall normal.
            const double repulsion = contact_repulsion(kernel, contact, s.w_reference, volumes, r);
            add = (repulsion / (r * p.mass[i])) * x_ij;
        } else {
            const ContactPair pair{x_ij, r, p.velocity[i] - p.velocity[j], volumes,
                                   p.mass[i] * p.mass[j] / (p.mass[i] + p.mass[j])};
            double dissipation = 0.0;
            add = contact_pair_force(kernel, contact, s.w_reference, pair, dissipation) / p.mass[i];
            heating += 0.5 * dissipation / p.mass[i];
        }
        for (int c = 0; c < 3; ++c) {
            a[c] += add[c];
        }
    }

    void operator()(Index i, Vec3& acceleration, double& heating_rate) const {
        const bool wall = p.wall_id[i] >= 0;
        double a[3];
        for (int c = 0; c < 3; ++c) {
            a[c] = wall ? 0.0 : s.gravity[c];
        }
        double heating = 0.0;
        const Vec3& xi = p.position[i];
        const double volume_i = p.mass[i] / p.density[i];
        const int key_i = key[i];
        const auto list = neighbours.neighbours(i);
        const double* factor_of_entry =
            entry_factor != nullptr ? entry_factor + neighbours.first_entry(i) : nullptr;
        for (std::size_t k = 0; k < list.size(); ++k) {
            const Index j = list[k];
            const Vec3& xj = p.position[j];
            double d[D];
            for (int c = 0; c < D; ++c) {
                d[c] = xi[c] - xj[c];
            }
            double r2 = d[0] * d[0] + d[1] * d[1];
            if constexpr (D == 3) {
                r2 += d[2] * d[2];
            }
            const bool same = key[j] == key_i;
            const bool in_support = r2 < s.support_squared && r2 != 0.0;
            if (!same) {
                if (in_support && s.use_contact && p.body_id[i] != p.body_id[j]) {
                    contact_pair(i, j, xi - xj, std::sqrt(r2), wall, volume_i, a, heating);
                }
                continue;
            }
            if (!s.current_pairs_act) {
                continue;
            }
            // Total-Lagrangian stress forces come from TotalLagrangian over the reference
            // pairs; the viscosity still acts between current neighbours. Pairs outside the
            // support are evaluated at r = support (finite) and not added. The kinematic pass
            // left W'(r)/r of the pairs inside the support in entry_factor when it is given
            // (its value there for the others is stale but not added).
            const bool need_r = factor_of_entry == nullptr || s.use_artificial_stress;
            const double r = need_r ? std::sqrt(in_support ? r2 : s.support_squared) : 0.0;
            const double f = factor_of_entry != nullptr ? factor_of_entry[k] : w.gradient_factor(r);
            double g[D];
            for (int c = 0; c < D; ++c) {
                g[c] = f * d[c];
            }
            continuum_pair(i, j, d, r, r2, g, in_support, a, heating);
        }
        acceleration = Vec3(a[0], a[1], a[2]);
        heating_rate = heating;
    }
};

} // namespace

void compute_accelerations(ParticleSet& p, const NeighbourList& neighbours,
                           const SmoothingKernel& kernel, const SphOptions& options,
                           const ForceInputs& in, std::vector<double>& heating_rate) {
    const Index n = p.size();
    heating_rate.assign(static_cast<std::size_t>(n), 0.0);
    const ForceSettings settings(kernel, options);
    const std::vector<int> key = continuum_keys(p);
    kernel.visit_shape([&](auto shape) {
        using Shape = decltype(shape);
        auto pass = [&](auto dimension) {
            const ForceRow<Shape, decltype(dimension)::value> row{
                p,
                neighbours,
                kernel,
                ShapeTerms<Shape>(kernel),
                settings,
                options.contact,
                in,
                key,
                in.entry_factor.empty() ? nullptr : in.entry_factor.data()};
#pragma omp parallel for schedule(dynamic, 128)
            for (Index i = 0; i < n; ++i) {
                row(i, p.acceleration[i], heating_rate[i]);
            }
        };
        if (kernel.dimension() == 2) {
            pass(std::integral_constant<int, 2>{});
        } else {
            pass(std::integral_constant<int, 3>{});
        }
    });
}

} // namespace grainload::sph
