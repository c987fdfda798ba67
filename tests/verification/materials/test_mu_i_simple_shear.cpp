// Verification: the mu(I) material driven in simple shear at an imposed shear rate and
// pressure, the experiment that defines the law (GDR MiDi 2004, plane shear; Jop, Forterre &
// Pouliquen 2006, eq. 2). The shear stress must rise elastically (tau = G gamma) until it meets
// mu(I) p, then stay at tau / p = mu(I) with the normal stresses at -p, for inertial numbers from
// the quasi-static 1e-8 to the collisional 1e4, at three pressures and in a rotated frame. The
// reference is Jop et al.'s formula evaluated here, in its own form, from the imposed rate and
// pressure.

#include "materials/mu_i_material.hpp"
#include "materials/voigt_algebra.hpp"
#include "tests/unit/materials/material_test_support.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <tuple>
#include <vector>

namespace grainload::materials {
namespace {

// Glass beads of Jop, Forterre & Pouliquen (2006): mu_s = tan 20.9 deg, mu_2 = tan 32.76 deg,
// I0 = 0.279, d = 0.53 mm; rho_s = 2500 kg/m^3 (soda-lime glass), bulk density 0.6 rho_s.
constexpr double kDegree = std::numbers::pi / 180.0;
const double kMuS = std::tan(20.9 * kDegree);
const double kMu2 = std::tan(32.76 * kDegree);
constexpr double kI0 = 0.279;
constexpr double kD = 0.53e-3;
constexpr double kRhoS = 2500.0;

MuIMaterial glass_beads() {
    return MuIMaterial(ElasticConstants::from_young(0.6 * kRhoS, 10e6, 0.3),
                       {kMuS, kMu2, kI0, kD, kRhoS});
}

/// Jop et al. (2006) eq. 2 as printed: mu_s + (mu_2 - mu_s) / (I0 / I + 1).
double jop_friction(double inertial_number) {
    return kMuS + (kMu2 - kMuS) / (kI0 / inertial_number + 1.0);
}

struct ShearRun {
    std::vector<double> shear_stress;  ///< sqrt(J2) after each step
    std::vector<double> pressure;      ///< -I1/3 after each step
    std::vector<double> normal_spread; ///< max |sigma_ii + p| in the shear frame
    std::vector<PlasticRegion> regions;
    std::vector<double> inertial_number; ///< the state's inertial number after each step
};

/// `steps` increments of engineering shear `increment` in the x-y plane of the frame rotated
/// by `r`, each over `time_step`, from the isotropic stress -p.
ShearRun shear(const MuIMaterial& m, double p, double increment, double time_step, int steps,
               const Mat3& r) {
    Voigt6 de = Voigt6::Zero();
    de(3) = increment;
    const Voigt6 de_rotated = testing::rotate_strain(r, de);
    Voigt6 stress = testing::rotate_stress(r, -p * voigt::identity());
    std::vector<double> state(static_cast<std::size_t>(m.state_size()), 0.0);
    ShearRun run;
    for (int step = 0; step < steps; ++step) {
        run.regions.push_back(m.update_over(de_rotated, time_step, stress, state, nullptr));
        const Voigt6 local = testing::rotate_stress(r.transpose(), stress);
        const double pressure = -voigt::trace(stress) / 3.0;
        run.pressure.push_back(pressure);
        run.shear_stress.push_back(voigt::norm(voigt::deviator(stress)) / std::sqrt(2.0));
        run.normal_spread.push_back((local.head<3>().array() + pressure).abs().maxCoeff());
        run.inertial_number.push_back(state[2]);
    }
    return run;
}

/// Round-off bound of the checks below: the trial, the invariants and the closed-form return
/// take a few tens of operations on values of the size of p, and the rotated frame adds two
/// 3x3 products; 1e-12 relative leaves a margin of ~1e3 over their accumulated rounding, and
/// is 1e-4 of the smallest rate effect checked (mu(1e-8) - mu_s = 9e-9 relative to mu_s is
/// checked separately, against its own bound).
constexpr double kRoundOff = 1e-12;

void expect_reaches_mu_of_i(double p, double inertial_number, const Mat3& r) {
    const MuIMaterial m = glass_beads();
    const double shear_modulus = m.elastic().shear_modulus;
    const double mu = jop_friction(inertial_number);
    // The imposed rate for this I at this pressure: gamma_dot = I sqrt(p / rho_s) / d.
    const double rate = inertial_number * std::sqrt(p / kRhoS) / kD;
    // 200 increments to the largest possible yield stress mu_2 p: the elastic rise is resolved.
    const double increment = kMu2 * p / (200.0 * shear_modulus);
    const ShearRun run = shear(m, p, increment, increment / rate, 600, r);
    int first_plastic = -1;
    for (int step = 0; step < 600; ++step) {
        const auto s = static_cast<std::size_t>(step);
        const double tau = run.shear_stress[s];
        EXPECT_NEAR(run.pressure[s], p, kRoundOff * p) << "step " << step;
        EXPECT_LE(run.normal_spread[s], kRoundOff * p) << "step " << step;
        if (run.regions[s] == PlasticRegion::elastic) {
            ASSERT_LT(first_plastic, 0) << "elastic again after yield at step " << step;
            // Hooke: tau = G gamma, gamma = (step + 1) increments.
            EXPECT_NEAR(tau, shear_modulus * increment * (step + 1), kRoundOff * p);
            continue;
        }
        ASSERT_EQ(run.regions[s], PlasticRegion::failure_surface) << "step " << step;
        if (first_plastic < 0) {
            first_plastic = step;
        }
        EXPECT_NEAR(tau / p, mu, kRoundOff * mu)
            << "I = " << inertial_number << ", p = " << p << " Pa, step " << step;
        // The state, and with it the frames' inertial_number, holds the imposed I.
        EXPECT_NEAR(run.inertial_number[s], inertial_number, kRoundOff * inertial_number)
            << "p = " << p << " Pa, step " << step;
    }
    // Yield where the elastic line G gamma meets mu(I) p (to round-off on either side).
    ASSERT_GE(first_plastic, 0) << "never yielded: I = " << inertial_number;
    const double onset = mu * p / (shear_modulus * increment);
    EXPECT_GE(first_plastic + 1.0, onset * (1.0 - kRoundOff)) << inertial_number;
    EXPECT_LE(first_plastic, onset * (1.0 + kRoundOff)) << inertial_number;
}

TEST(MuISimpleShear, FlowsAtMuOfIOverTwelveDecadesOfI) {
    for (const double p : {100.0, 1e3, 1e4}) {
        for (const double i : {1e-8, 1e-4, 1e-3, 1e-2, 0.1, kI0, 1.0, 10.0, 1e4}) {
            expect_reaches_mu_of_i(p, i, Mat3::Identity());
        }
    }
}

TEST(MuISimpleShear, FlowsAtMuOfIInARotatedFrame) {
    // Shear in an arbitrary plane: sqrt(J2) / p must be the same mu(I), the normal stresses of
    // the shear frame stay at -p (the invariants, not the x-y components, carry the law).
    for (const double i : {1e-3, 0.1, 10.0}) {
        expect_reaches_mu_of_i(1e3, i, testing::some_rotation());
    }
}

TEST(MuISimpleShear, TendsToMuSAndMu2AtTheEnds) {
    // The material's limits, beside the law's: at I = 1e-8 the flowing tau / p is within
    // (mu_2 - mu_s) I / I0 = 9.4e-9 of mu_s (the law's first-order term, bounded by 1e-8), at
    // I = 1e4 within (mu_2 - mu_s) I0 / I = 7.3e-6 of mu_2 (bounded by 1e-5).
    const MuIMaterial m = glass_beads();
    const double p = 1e3;
    const double increment = kMu2 * p / (200.0 * m.elastic().shear_modulus);
    for (const auto& [i, reference, bound] :
         {std::tuple{1e-8, kMuS, 1e-8}, std::tuple{1e4, kMu2, 1e-5}}) {
        const double rate = i * std::sqrt(p / kRhoS) / kD;
        const ShearRun run = shear(m, p, increment, increment / rate, 600, Mat3::Identity());
        EXPECT_EQ(run.regions.back(), PlasticRegion::failure_surface);
        EXPECT_NEAR(run.shear_stress.back() / p, reference, bound) << "I = " << i;
    }
}

} // namespace
} // namespace grainload::materials
