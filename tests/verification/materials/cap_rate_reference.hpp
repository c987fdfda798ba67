#pragma once
// An independent rate-equation reference for the generalized cap in uniaxial strain.

// An independent reference for the generalized cap model along uniaxial strain: the rate
// equations of the model (associated flow, consistency, the MAT_025 hardening law) integrated
// explicitly in very small sub-steps. It shares nothing with materials/cap_return.cpp: the
// geometry comes from cap_test_support.hpp (restated from the MAT_025 definitions), the
// integration is forward Euler of the rate problem (the continuum elastoplastic tangent of the
// flowing surfaces, chosen by the complementarity conditions, drift corrected), with the
// elastic-plastic transitions located by bisection, not a backward-Euler return. Its error is
// first order in the sub-step; the tests measure it by halving the sub-step.

#include "tests/unit/materials/cap_test_support.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace grainload::materials::testing {

/// State of a uniaxial-strain sample in the invariant plane, compression positive: I1, the
/// signed deviator t = (sigma_axial - sigma_lateral) / sqrt(3) (sqrt(J2) = |t|), the hardening
/// parameter kappa and the plastic volumetric strain (compaction positive).
struct RateState {
    double i1 = 0.0;
    double t = 0.0;
    double kappa = 0.0;
    double evp = 0.0;
};

/// One yield function f(I1, q, kappa) <= 0 with its derivatives.
struct Yield {
    double f = 0.0;
    double f_i1 = 0.0;
    double f_q = 0.0;
    double f_kappa = 0.0;
};

class CapRateReference {
  public:
    CapRateReference(cap::Parameters p, double bulk, double shear)
        : p_(p), bulk_(bulk), shear_(shear) {}

    /// kappa0 from X(kappa0) = X0 and eps_v^p = 0 (MAT_025).
    RateState initial() const {
        RateState s;
        s.kappa = solve_scalar([&](double k) { return x_of(p_, k) - p_.X0; }, 0.0,
                               p_.k + std::abs(p_.X0) + 1.0);
        return s;
    }

    /// Apply an axial strain increment `de` (compression positive) in `substeps` equal parts.
    void strain(RateState& s, double de, long substeps) const {
        for (long i = 0; i < substeps; ++i) {
            substep(s, de / static_cast<double>(substeps));
        }
    }

    /// Compression-positive axial and lateral stress of a state.
    static std::pair<double, double> stresses(const RateState& s) {
        // I1 = s_a + 2 s_l, t = (s_a - s_l) / sqrt(3).
        const double lateral = (s.i1 - std::sqrt(3.0) * s.t) / 3.0;
        return {lateral + std::sqrt(3.0) * s.t, lateral};
    }

  private:
    double envelope(double i1) const {
        return p_.k + p_.theta * i1 - p_.gamma * std::exp(-p_.beta * i1);
    }
    double envelope_slope(double i1) const {
        return p_.theta + p_.gamma * p_.beta * std::exp(-p_.beta * i1);
    }
    /// d eps_v^p / d kappa of eps_v^p = W (1 - exp(-D (X(kappa) - X0))).
    double hardening_modulus(double kappa) const {
        const double h = 1e-7 * (std::abs(kappa) + p_.k + 1.0);
        const double dx = (x_of(p_, kappa + h) - x_of(p_, kappa - h)) / (2.0 * h);
        return p_.W * p_.D * std::exp(-p_.D * (x_of(p_, kappa) - p_.X0)) * dx;
    }

    Yield failure(double i1, double q) const {
        return {q - envelope(i1), -envelope_slope(i1), 1.0, 0.0};
    }
    /// Cap fc = sqrt(<I1 - L>^2 / R^2 + q^2) - B(kappa): the ellipse right of its centre and,
    /// left of it, the flat top sqrt(J2) = B (active only while kappa < 0).
    Yield cap(double i1, double q, double kappa, double i1_dir, double q_dir) const {
        const double u = std::max(i1 - l_of(p_, kappa), 0.0);
        double r = std::sqrt(u * u / (p_.R * p_.R) + q * q);
        double n_i1 = 0.0;
        double n_q = 1.0;
        if (r > 1e-12 * (p_.k + std::abs(kappa))) {
            n_i1 = u / (p_.R * p_.R * r);
            n_q = q / r;
        } else {
            // At the centre of a zero-size cap the normal is that of the loading direction.
            const double ru = std::sqrt(i1_dir * i1_dir / (p_.R * p_.R) + q_dir * q_dir);
            n_i1 = i1_dir / (p_.R * p_.R * ru);
            n_q = q_dir / ru;
        }
        const double h = 1e-7 * (std::abs(kappa) + p_.k + 1.0);
        const double db = (b_of(p_, kappa + h) - b_of(p_, kappa - h)) / (2.0 * h);
        const double dl = (l_of(p_, kappa + h) - l_of(p_, kappa - h)) / (2.0 * h);
        return {r - b_of(p_, kappa), n_i1, n_q, -n_i1 * dl - db};
    }
    Yield tension(double i1) const { return {-i1 - p_.tension, -1.0, 0.0, 0.0}; }

    static int at(const std::array<int, 3>& a, Eigen::Index i) {
        return a[static_cast<std::size_t>(i)];
    }

    /// The three yield functions at a state, gradients there; a zero-size cap (the origin of
    /// the wagon set) takes the normal of the loading direction (di1, dq).
    std::array<Yield, 3> yields(const RateState& s, double di1, double dq) const {
        const double q = std::abs(s.t);
        return {failure(s.i1, q), cap(s.i1, q, s.kappa, di1, dq), tension(s.i1)};
    }

    /// The state after an axial strain `de` with the surfaces in `mask` flowing, or nothing when
    /// their multipliers are not all >= 0 or a surface outside `mask` that is already reached
    /// would be violated at once (the complementarity conditions of the rate problem).
    std::optional<RateState> trial_step(const RateState& s, double de, unsigned mask,
                                        unsigned reached) const {
        const double di1 = 3.0 * bulk_ * de;
        const double dq = 2.0 / std::sqrt(3.0) * shear_ * de * (s.t >= 0.0 ? 1.0 : -1.0);
        const std::array<Yield, 3> y = yields(s, di1, dq);
        std::array<int, 3> flowing{};
        Eigen::Index n = 0;
        for (int i = 0; i < 3; ++i) {
            if ((mask >> i) & 1U) {
                flowing[static_cast<std::size_t>(n++)] = i;
            }
        }
        const double hk = hardening_modulus(s.kappa);
        // Rate of f_i per multiplier of surface j, and the elastic part.
        const auto coupling = [&](int i, int j) {
            return -9.0 * bulk_ * y[i].f_i1 * y[j].f_i1 - shear_ * y[i].f_q * y[j].f_q +
                   y[i].f_kappa * 3.0 * y[j].f_i1 / hk;
        };
        const auto elastic = [&](int i) { return y[i].f_i1 * di1 + y[i].f_q * dq; };
        // At most three surfaces: fixed-capacity matrices, no allocation per sub-step.
        using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
        using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
        SmallVector lambda = SmallVector::Zero(n);
        if (n > 0) {
            Small a(n, n);
            SmallVector b(n);
            for (Eigen::Index i = 0; i < n; ++i) {
                // Drift corrected: f_i + df_i = 0 at the end of the step.
                b(i) = -(y[at(flowing, i)].f + elastic(at(flowing, i)));
                for (Eigen::Index j = 0; j < n; ++j) {
                    a(i, j) = coupling(at(flowing, i), at(flowing, j));
                }
            }
            lambda = a.partialPivLu().solve(b);
            if ((lambda.array() < 0.0).any() || !lambda.allFinite()) {
                return std::nullopt;
            }
        }
        for (int i = 0; i < 3; ++i) {
            if (((reached >> i) & 1U) && !((mask >> i) & 1U)) {
                double rate = y[i].f + elastic(i);
                for (Eigen::Index j = 0; j < n; ++j) {
                    rate += coupling(i, at(flowing, j)) * lambda(j);
                }
                if (rate > tolerance(y[i])) {
                    return std::nullopt;
                }
            }
        }
        double devp = 0.0;
        double dq_plastic = 0.0;
        for (Eigen::Index j = 0; j < n; ++j) {
            devp += 3.0 * lambda(j) * y[at(flowing, j)].f_i1;
            dq_plastic += lambda(j) * y[at(flowing, j)].f_q;
        }
        RateState next = s;
        next.i1 = s.i1 + di1 - 3.0 * bulk_ * devp;
        const double q = std::abs(s.t) + dq - shear_ * dq_plastic;
        next.t = (s.t >= 0.0 ? 1.0 : -1.0) * q;
        next.kappa = s.kappa + devp / hk;
        next.evp = s.evp + devp;
        return next;
    }

    /// Slack on f for "reached": far below the stress scale of the sets, far above round-off.
    double tolerance(const Yield&) const { return 1e-9 * (p_.k + std::abs(p_.X0)); }

    /// One sub-step: the flowing set is the subset of the reached surfaces (f >= -slack) that
    /// satisfies the complementarity conditions; a surface not reached that the step would
    /// violate cuts the step where it is met (bisection), so the elastic-plastic transitions are
    /// located, not stepped over.
    void substep(RateState& s, double de) const {
        double remaining = de;
        for (int guard = 0; guard < 200 && remaining != 0.0; ++guard) {
            const std::array<Yield, 3> y = yields(s, remaining, remaining);
            unsigned reached = 0;
            for (int i = 0; i < 3; ++i) {
                if (y[i].f >= -tolerance(y[i])) {
                    reached |= 1U << i;
                }
            }
            const auto step = [&](double h) -> std::optional<RateState> {
                for (unsigned mask : {0U, 1U, 2U, 4U, 3U, 5U, 6U, 7U}) {
                    if ((mask & reached) == mask) {
                        if (auto next = trial_step(s, h, mask, reached)) {
                            return next;
                        }
                    }
                }
                return std::nullopt;
            };
            const auto violates = [&](const RateState& next) {
                const std::array<Yield, 3> z = yields(next, 0.0, 1.0);
                for (int i = 0; i < 3; ++i) {
                    if (!((reached >> i) & 1U) && z[i].f > tolerance(z[i])) {
                        return true;
                    }
                }
                return false;
            };
            std::optional<RateState> next = step(remaining);
            if (!next) {
                ADD_FAILURE() << "no flowing set satisfies the rate problem";
                return;
            }
            double h = remaining;
            if (violates(*next)) {
                double lo = 0.0;
                double hi = remaining;
                for (int k = 0; k < 60; ++k) {
                    const double mid = 0.5 * (lo + hi);
                    const auto at = step(mid);
                    (at && !violates(*at) ? lo : hi) = mid;
                }
                h = hi; // just past the contact: the surface counts as reached next time
                next = step(h);
            }
            s = *next;
            remaining -= h;
        }
    }

    cap::Parameters p_;
    double bulk_;
    double shear_;
};

} // namespace grainload::materials::testing
