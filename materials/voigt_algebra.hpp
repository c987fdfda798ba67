#pragma once
// Small tensor helpers on Voigt vectors.

#include "io/types.hpp"

#include <cmath>

// Small tensor helpers on the Voigt vectors of io/types.hpp (order xx, yy, zz, xy, yz, zx).
// A "stress-like" vector holds tensor components; the double contraction of two of them counts
// each shear component twice. The stiffness matrices below map ENGINEERING strain to stress.
namespace grainload::materials::voigt {

/// Second-order identity (Kronecker delta) as a stress-like vector.
inline Voigt6 identity() {
    Voigt6 one;
    one << 1.0, 1.0, 1.0, 0.0, 0.0, 0.0;
    return one;
}

inline double trace(const Voigt6& a) {
    return a(0) + a(1) + a(2);
}

inline Voigt6 deviator(const Voigt6& a) {
    return a - (trace(a) / 3.0) * identity();
}

/// Double contraction a:b of two stress-like vectors.
inline double contract(const Voigt6& a, const Voigt6& b) {
    return a.head<3>().dot(b.head<3>()) + 2.0 * a.tail<3>().dot(b.tail<3>());
}

/// Frobenius norm ||a|| = sqrt(a:a) of a stress-like vector.
inline double norm(const Voigt6& a) {
    return std::sqrt(contract(a, a));
}

/// Engineering strain -> tensor (stress-like) components: shear halved.
inline Voigt6 tensor_from_engineering(const Voigt6& e) {
    Voigt6 t = e;
    t.tail<3>() *= 0.5;
    return t;
}

/// Tensor (stress-like) components -> engineering strain: shear doubled.
inline Voigt6 engineering_from_tensor(const Voigt6& t) {
    Voigt6 e = t;
    e.tail<3>() *= 2.0;
    return e;
}

/// 2G I_dev as a matrix from engineering strain to stress: the deviatoric elastic stiffness.
inline Matrix6 deviatoric_stiffness(double shear_modulus) {
    Matrix6 p = Matrix6::Zero();
    p.topLeftCorner<3, 3>().setConstant(-2.0 * shear_modulus / 3.0);
    for (int i = 0; i < 3; ++i) {
        p(i, i) += 2.0 * shear_modulus;
        p(i + 3, i + 3) = shear_modulus;
    }
    return p;
}

/// a (x) b as a matrix from engineering strain to stress, i.e. (a (x) b) : d_eps = a (b : d_eps)
/// with a, b stress-like. Because b is stress-like and d_eps engineering, b : d_eps = b . d_eps.
inline Matrix6 outer(const Voigt6& a, const Voigt6& b) {
    return a * b.transpose();
}

} // namespace grainload::materials::voigt
