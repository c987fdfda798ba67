#pragma once
// What the generalized-cap tests share: the thesis sand and independent restatements.

// Helpers of the generalized-cap tests: the thesis parameter set (section 7.2), an independent
// restatement of the model's closed-form pieces, and a mixed stress/strain controlled step.

#include "materials/generalized_cap.hpp"
#include "tests/unit/materials/material_test_support.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace grainload::materials::testing {

inline constexpr double kMPa = 1e6;

/// Thesis section 7.2 sand, constants in MPa converted to Pa (the thesis gives them unitless,
/// consistent with MPa).
inline cap::Parameters thesis_cap() {
    cap::Parameters p;
    p.k = 0.03858 * kMPa;
    p.theta = 0.03;
    p.gamma = 0.03858 * kMPa;
    p.beta = 9.0 / kMPa;
    p.D = 7.25 / kMPa;
    p.W = 0.18;
    p.X0 = 0.0;
    p.R = 2.0;
    p.tension = 0.0;
    return p;
}

inline ElasticConstants thesis_elastic() {
    return ElasticConstants::from_bulk_shear(2099.0, 30.62e9, 8.23e9);
}

/// Thesis section 7.4 wagon sand/gravel: F(0) = k > 0 and gamma = 0, so with MAT_025's X0 = 0
/// the hardening parameter starts at kappa0 = -R k / (1 + R theta) < 0 and the initial cap is
/// the single point I1 = 0 (X = L = 0, B = 0).
inline cap::Parameters wagon_cap() {
    cap::Parameters p;
    p.k = 0.00106 * kMPa;
    p.theta = 0.004;
    p.gamma = 0.0;
    p.beta = 1.0 / kMPa;
    p.D = 7.25 / kMPa;
    p.W = 2.58;
    p.X0 = 0.0;
    p.R = 2.0;
    return p;
}

inline constexpr double kKsi = 6.894757293168361e6;

/// A sand of the McCormick Ranch form used by Sandler & Rubin (1979) and Simo et al. (1988),
/// in ksi (constants as they are commonly quoted, not checked against the papers here): k =
/// 0.25 ksi, theta = 0, gamma = 0.18 ksi, B1 = 0.67 1/ksi, R = 2.5, D = 0.67 1/ksi, W = 0.066,
/// K = 66.7 ksi, G = 40 ksi, T = 0. X0 is lowered to 0.1 ksi < X(0) = 0.175 ksi so that
/// kappa0 < 0 (about -0.057 ksi).
inline cap::Parameters sand_cap() {
    cap::Parameters p;
    p.k = 0.25 * kKsi;
    p.theta = 0.0;
    p.gamma = 0.18 * kKsi;
    p.beta = 0.67 / kKsi;
    p.D = 0.67 / kKsi;
    p.W = 0.066;
    p.X0 = 0.1 * kKsi;
    p.R = 2.5;
    return p;
}

/// The same sand with a tension cutoff T = 0.3 ksi: F(-T) = 0.030 ksi < B(kappa0) = 0.04 ksi
/// leaves a piece of envelope between the cutoff and the clamped cap's flat top, so that every
/// region of a clamped centre is reachable.
inline cap::Parameters cemented_sand_cap() {
    cap::Parameters p = sand_cap();
    p.tension = 0.3 * kKsi;
    return p;
}

inline ElasticConstants sand_elastic() {
    return ElasticConstants::from_bulk_shear(1800.0, 66.7 * kKsi, 40.0 * kKsi);
}

/// A parameter set with its elasticity and a stress scale (about the cap position where the
/// tests probe it).
struct CapSet {
    std::string name;
    cap::Parameters p;
    ElasticConstants elastic;
    double scale = 0.0;
};

inline std::vector<CapSet> cap_sets() {
    return {{"thesis", thesis_cap(), thesis_elastic(), 1.0 * kMPa},
            {"wagon", wagon_cap(), thesis_elastic(), 0.01 * kMPa},
            {"sand", sand_cap(), sand_elastic(), 1.0 * kKsi},
            {"cemented_sand", cemented_sand_cap(), sand_elastic(), 1.0 * kKsi}};
}

/// The cap geometry restated from the MAT_025 definitions (LS-DYNA keyword manual,
/// *MAT_GEOLOGIC_CAP_MODEL), independently of materials/cap_surfaces: X(kappa) = kappa +
/// R F(kappa), L(kappa) = max(kappa, 0), half-height B = (X - L) / R.
inline double x_of(const cap::Parameters& p, double kappa) {
    return kappa + p.R * (p.k + p.theta * kappa - p.gamma * std::exp(-p.beta * kappa));
}

inline double l_of(const cap::Parameters& p, double kappa) {
    return p.semantics == cap::Semantics::mat025 && p.R > 0.0 ? std::max(kappa, 0.0) : kappa;
}

inline double b_of(const cap::Parameters& p, double kappa) {
    return p.R > 0.0 ? std::max((x_of(p, kappa) - l_of(p, kappa)) / p.R, 0.0)
                     : p.k + p.theta * kappa - p.gamma * std::exp(-p.beta * kappa);
}

/// Failure envelope written from the model's definition, not from the library: sqrt(J2) = k + theta
/// I1 - gamma exp(-B1 I1), compression positive.
inline double envelope_of(const cap::Parameters& p, double i1) {
    return p.k + p.theta * i1 - p.gamma * std::exp(-p.beta * i1);
}

/// Compression-positive invariants (I1, sqrt(J2)) of a tension-positive stress.
inline std::array<double, 2> invariants(const Voigt6& stress) {
    const double i1 = -stress.head<3>().sum();
    Voigt6 s = -stress;
    s.head<3>().array() -= i1 / 3.0;
    return {i1, std::sqrt(0.5 * s.head<3>().squaredNorm() + s.tail<3>().squaredNorm())};
}

/// Scalar Newton with a numerical derivative, for the tests' own closed forms.
template <class F> double solve_scalar(F f, double x, double scale) {
    for (int i = 0; i < 200; ++i) {
        const double h = 1e-7 * scale;
        const double slope = (f(x + h) - f(x - h)) / (2.0 * h);
        const double step = f(x) / slope;
        x -= step;
        if (std::abs(step) < 1e-15 * scale) {
            break;
        }
    }
    return x;
}

/// Residual of the stress-controlled components after one update; fills stress and state.
inline Eigen::VectorXd control_residual(const Material& m, const Voigt6& start,
                                        const std::vector<double>& state0, const Voigt6& increment,
                                        const std::vector<int>& free, const Voigt6& target,
                                        Voigt6& stress, std::vector<double>& state,
                                        Matrix6& tangent, PlasticRegion& region) {
    stress = start;
    state = state0;
    region = m.update(increment, stress, state, &tangent);
    Eigen::VectorXd r(static_cast<Eigen::Index>(free.size()));
    for (std::size_t a = 0; a < free.size(); ++a) {
        r(static_cast<Eigen::Index>(a)) = stress(free[a]) - target(free[a]);
    }
    return r;
}

/// One step with the strain components where `controlled` is false prescribed by `increment`
/// and the stress components where it is true driven to `target`: Newton on the consistent
/// tangent (elastic predictor first, and at the apex where the tangent is singular), with
/// backtracking so that it also converges across region changes.
inline PlasticRegion mixed_step(const Material& m, Voigt6& stress, std::vector<double>& state,
                                Voigt6& increment, const std::array<bool, 6>& controlled,
                                const Voigt6& target) {
    std::vector<int> free;
    for (int i = 0; i < 6; ++i) {
        if (controlled[static_cast<std::size_t>(i)]) {
            free.push_back(i);
        }
    }
    const Eigen::Index n = static_cast<Eigen::Index>(free.size());
    Voigt6 trial;
    std::vector<double> trial_state;
    Matrix6 tangent;
    PlasticRegion region = PlasticRegion::elastic;
    Eigen::VectorXd residual = control_residual(m, stress, state, increment, free, target, trial,
                                                trial_state, tangent, region);
    const double tolerance = 1e-11 * (target.norm() + 1.0);
    for (int iteration = 0; iteration < 100; ++iteration) {
        if (n == 0 || residual.cwiseAbs().maxCoeff() <= tolerance) {
            stress = trial;
            state = trial_state;
            return region;
        }
        const Matrix6 jacobian_full =
            (iteration == 0 || region == PlasticRegion::apex) ? m.elastic().stiffness() : tangent;
        Eigen::MatrixXd jacobian(n, n);
        for (Eigen::Index a = 0; a < n; ++a) {
            for (Eigen::Index b = 0; b < n; ++b) {
                jacobian(a, b) = jacobian_full(free[a], free[b]);
            }
        }
        const Eigen::VectorXd correction = jacobian.fullPivLu().solve(residual);
        double alpha = 1.0;
        for (int halving = 0; halving < 30; ++halving, alpha *= 0.5) {
            Voigt6 candidate = increment;
            for (Eigen::Index a = 0; a < n; ++a) {
                candidate(free[a]) -= alpha * correction(a);
            }
            const Eigen::VectorXd r = control_residual(m, stress, state, candidate, free, target,
                                                       trial, trial_state, tangent, region);
            if (r.norm() < residual.norm() || halving == 29) {
                increment = candidate;
                residual = r;
                break;
            }
        }
    }
    ADD_FAILURE() << "mixed-control step did not converge";
    return region;
}

/// Hydrostatic compression (tension positive: negative strains) by volumetric strain ev > 0.
inline Voigt6 hydrostatic_strain(double ev) {
    Voigt6 e = Voigt6::Zero();
    e.head<3>().setConstant(-ev / 3.0);
    return e;
}

} // namespace grainload::materials::testing
