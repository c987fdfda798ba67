#include "fem/plane_stress_point.hpp"

#include <cmath>
#include <stdexcept>

namespace grainload::fem {

namespace {

/// Voigt6 positions of the in-plane components 11, 22, 12 and of the normal component 33.
constexpr int kInPlane[3] = {0, 1, 3};
constexpr int kNormal = 2;
constexpr int kMaxIterations = 30;

Voigt6 strain_increment(const ShellVector& strain, const Voigt6& committed, double d33) {
    Voigt6 d = Voigt6::Zero();
    d(0) = strain(0) - committed(0);
    d(1) = strain(1) - committed(1);
    d(kNormal) = d33;
    d(3) = strain(2) - committed(3);
    return d;
}

} // namespace

ShellVector plane_stress_update(const materials::Material& material, const ShellVector& strain,
                                const MaterialPoint& committed, MaterialPoint& point,
                                ShellMatrix* tangent) {
    const double nu = material.elastic().poisson();
    // Elastic plane-stress guess of d(eps_33); exact for linear elasticity.
    double d33 =
        -nu / (1.0 - nu) * (strain(0) - committed.strain(0) + strain(1) - committed.strain(1));
    Matrix6 d6;
    int iteration = 0;
    for (;; ++iteration) {
        point.stress = committed.stress;
        point.state = committed.state;
        const Voigt6 increment = strain_increment(strain, committed.strain, d33);
        material.update(increment, point.stress, point.state, &d6);
        const double scale =
            std::abs(point.stress(0)) + std::abs(point.stress(1)) + std::abs(point.stress(3));
        // 1e-8 of the in-plane stress: return maps are exact only to ~1e-9 relative.
        if (std::abs(point.stress(kNormal)) <= 1e-8 * scale || point.stress(kNormal) == 0.0) {
            point.strain = committed.strain + increment;
            break;
        }
        if (iteration == kMaxIterations) {
            throw std::runtime_error("plane-stress iteration did not converge (sigma_33 = " +
                                     std::to_string(point.stress(kNormal)) + " Pa)");
        }
        d33 -= point.stress(kNormal) / d6(kNormal, kNormal);
    }
    const double shear = kShearCorrection * material.elastic().shear_modulus;
    point.strain(4) = strain(3);
    point.strain(5) = strain(4);
    point.stress(4) = shear * strain(3);
    point.stress(5) = shear * strain(4);

    ShellVector stress;
    stress << point.stress(0), point.stress(1), point.stress(3), point.stress(4), point.stress(5);
    if (tangent != nullptr) {
        tangent->setZero();
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                const int a = kInPlane[i];
                const int b = kInPlane[j];
                (*tangent)(i, j) =
                    d6(a, b) - d6(a, kNormal) * d6(kNormal, b) / d6(kNormal, kNormal);
            }
        }
        (*tangent)(3, 3) = shear;
        (*tangent)(4, 4) = shear;
    }
    return stress;
}

} // namespace grainload::fem
