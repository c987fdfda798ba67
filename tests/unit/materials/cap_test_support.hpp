#pragma once

// Helpers of the generalized-cap tests: the thesis parameter set (section 7.2), an independent
// restatement of the model's closed-form pieces, and a mixed stress/strain controlled step.

#include "materials/generalized_cap.hpp"
#include "tests/unit/materials/material_test_support.hpp"

#include <Eigen/Dense>
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

/// Failure envelope written from the brief, not from the library: sqrt(J2) = k + theta I1 -
/// gamma exp(-B1 I1), compression positive.
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
