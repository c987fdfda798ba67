// Verification: uniaxial tension-compression cycle of von Mises with linear mixed hardening,
// driven through the material-point driver with mixed control (sigma_yy = sigma_zz = 0),
// against the closed-form 1D elasto-plastic answer (thesis section 4.6.2, fig. 4.6.2.1).

#include "tests/unit/materials/material_test_support.hpp"
#include "tests/verification/materials/driver_support.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <string>

namespace grainload::materials {
namespace {

constexpr double kE = 200e9;
constexpr double kTangent = 5e9;
constexpr double kYield = 250e6;
constexpr double kStrain = 0.01;

std::string driver(double beta) {
    return R"(
[[material]]
model = "von_mises"
density = "7850 kg/m^3"
youngs_modulus = "200 GPa"
poisson_ratio = 0.3
yield_stress = "250 MPa"
tangent_modulus = "5 GPa"
hardening_beta = )" +
           std::to_string(beta) + R"(
[path]
[[path.segment]]
steps = 37
strain_increment = { xx = 0.01 }
stress = { yy = "0 Pa", zz = "0 Pa" }
[[path.segment]]
steps = 83
strain_increment = { xx = -0.02 }
stress = { yy = "0 Pa", zz = "0 Pa" }
)";
}

/// Closed-form 1D answer. Loading: elastic, then slope E_T. With E_p = E E_T / (E - E_T) and
/// plastic strain ep = (s_max - s0) / E_p at the turn, the centre is (1 - beta) E_p ep and the
/// radius s0 + beta E_p ep, so the reverse yield is at s_r = centre - radius
/// (-s_max for beta = 1, s_max - 2 s0 for beta = 0: Bauschinger).
struct Uniaxial {
    double beta;
    double plastic_modulus = kE * kTangent / (kE - kTangent);
    double peak = kYield + kTangent * (kStrain - kYield / kE);
    double reverse_yield() const {
        const double ep = (peak - kYield) / plastic_modulus;
        return (1.0 - beta) * plastic_modulus * ep - (kYield + beta * plastic_modulus * ep);
    }
    double loading(double eps) const {
        return std::min(kE * eps, kYield + kTangent * (eps - kYield / kE));
    }
    double unloading(double eps) const {
        const double s_r = reverse_yield();
        const double eps_r = kStrain - (peak - s_r) / kE;
        return std::max(peak + kE * (eps - kStrain), s_r + kTangent * (eps - eps_r));
    }
};

void check_cycle(double beta, double expected_reverse_yield) {
    const auto run = testing::run_driver_text(driver(beta));
    const Uniaxial reference{beta};
    ASSERT_NEAR(reference.reverse_yield(), expected_reverse_yield, 1e-6 * kYield);
    double worst = 0.0;
    for (const auto& r : run.records) {
        const double eps = r.strain(0);
        const double exact = r.step <= 37 ? reference.loading(eps) : reference.unloading(eps);
        worst = std::max(worst, std::abs(r.stress(0) - exact));
        // Lateral stresses are held at zero by Newton, tolerance 1e-10 of the stress level.
        EXPECT_LT(std::abs(r.stress(1)) + std::abs(r.stress(2)), 1e-9 * kYield);
    }
    // The radial return is exact on this radial (uniaxial) path and Newton converges to 1e-10
    // of the stress: the whole curve agrees with the closed form to 1e-9 of sigma_0.
    EXPECT_LT(worst, 1e-9 * kYield) << "beta " << beta;
    ::testing::Test::RecordProperty("max_stress_error_over_yield_beta_" + testing::figure(beta),
                                    testing::figure(worst / kYield));
}

TEST(VonMisesUniaxialCycle, IsotropicHardeningReversesAtMinusPeak) {
    check_cycle(1.0, -(kYield + kTangent * (kStrain - kYield / kE)));
}

TEST(VonMisesUniaxialCycle, KinematicHardeningShowsBauschinger) {
    check_cycle(0.0, kYield + kTangent * (kStrain - kYield / kE) - 2.0 * kYield);
}

TEST(VonMisesUniaxialCycle, MixedHardening) {
    const Uniaxial half{0.5};
    check_cycle(0.5, half.reverse_yield());
}

} // namespace
} // namespace grainload::materials
