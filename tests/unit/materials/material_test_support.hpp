#pragma once
// What the material tests share: tangents by differences, Voigt helpers, strain paths.

// Helpers shared by the material unit and verification tests: finite-difference tangents,
// Voigt <-> tensor conversions and rotations, and strain-driven paths.

#include "materials/material.hpp"

#include <Eigen/Dense>
#include <cstdio>
#include <string>
#include <vector>

namespace grainload::materials::testing {

inline std::vector<double> initial_state(const Material& m) {
    std::vector<double> state(static_cast<std::size_t>(m.state_size()), 0.0);
    m.initialise_state(state);
    return state;
}

/// Central finite difference of the stress after one update with respect to the (engineering)
/// strain increment, from the same start stress and state each time.
inline Matrix6 finite_difference_tangent(const Material& m, const Voigt6& stress,
                                         const std::vector<double>& state, const Voigt6& increment,
                                         double h) {
    Matrix6 d;
    for (int j = 0; j < 6; ++j) {
        Voigt6 plus_eps = increment;
        Voigt6 minus_eps = increment;
        plus_eps(j) += h;
        minus_eps(j) -= h;
        Voigt6 plus = stress;
        Voigt6 minus = stress;
        std::vector<double> s1 = state;
        std::vector<double> s2 = state;
        m.update(plus_eps, plus, s1, nullptr);
        m.update(minus_eps, minus, s2, nullptr);
        d.col(j) = (plus - minus) / (2.0 * h);
    }
    return d;
}

/// max |D - D_fd| relative to max |D_ref| (the elastic stiffness where D itself may vanish).
inline double relative_tangent_error(const Matrix6& d, const Matrix6& d_fd, const Matrix6& ref) {
    return (d - d_fd).cwiseAbs().maxCoeff() / ref.cwiseAbs().maxCoeff();
}

/// A measured figure for RecordProperty (gtest XML), in scientific notation.
inline std::string figure(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3e", value);
    return buffer;
}

inline Mat3 stress_tensor(const Voigt6& s) {
    Mat3 t;
    t << s(0), s(3), s(5), s(3), s(1), s(4), s(5), s(4), s(2);
    return t;
}

inline Voigt6 stress_voigt(const Mat3& t) {
    Voigt6 s;
    s << t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(1, 2), t(2, 0);
    return s;
}

inline Voigt6 rotate_stress(const Mat3& r, const Voigt6& s) {
    return stress_voigt(r * stress_tensor(s) * r.transpose());
}

/// Engineering-shear strain rotated as a tensor.
inline Voigt6 rotate_strain(const Mat3& r, const Voigt6& e) {
    Voigt6 t = e;
    t.tail<3>() *= 0.5;
    Voigt6 out = rotate_stress(r, t);
    out.tail<3>() *= 2.0;
    return out;
}

inline Mat3 some_rotation() {
    return (Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()) *
            Eigen::AngleAxisd(-1.3, Vec3::UnitZ()))
        .toRotationMatrix();
}

/// Apply `total` in `steps` equal increments from `stress`/`state`; returns the final stress.
inline Voigt6 drive(const Material& m, Voigt6 stress, std::vector<double>& state,
                    const Voigt6& total, int steps) {
    for (int i = 0; i < steps; ++i) {
        m.update(total / steps, stress, state, nullptr);
    }
    return stress;
}

/// Strain increment whose elastic trial stress from zero is `stress`.
inline Voigt6 strain_for_stress(const Material& m, const Voigt6& stress) {
    return m.elastic().stiffness().fullPivLu().solve(stress);
}

} // namespace grainload::materials::testing
