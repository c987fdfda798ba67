// Verification of the generalized cap model along laboratory paths with closed-form answers:
// conventional triaxial compression (peak on the failure envelope), drained simple shear
// (plateau, associated dilatancy until the cap reaches the stress point), and tension paths
// (apex and tension cutoff). Parameters: thesis section 7.2 sand unless noted.

#include "tests/unit/materials/cap_test_support.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

namespace grainload::materials::testing {
namespace {

constexpr double kBulk = 30.62e9;

Voigt6 all_normal(double value) {
    Voigt6 v = Voigt6::Zero();
    v.head<3>().setConstant(value);
    return v;
}

/// Start from rest and compress hydrostatically to the mean pressure p (stress controlled).
Voigt6 consolidate(const GeneralizedCap& m, std::vector<double>& state, double pressure) {
    Voigt6 stress = Voigt6::Zero();
    for (int i = 1; i <= 10; ++i) {
        Voigt6 zero = Voigt6::Zero();
        mixed_step(m, stress, state, zero, {true, true, true, false, false, false},
                   all_normal(-pressure * i / 10.0));
    }
    return stress;
}

/// Axial compression with the lateral stresses held at -p, on a sample consolidated to
/// 2p + 1/3 MPa and unloaded to p, so that the cap centre L lies beyond the peak's I1 and the
/// path meets the failure surface itself; returns the largest axial compression reached and
/// the last region. (A normally consolidated sample rides the hardening cap and approaches the
/// envelope only asymptotically, as the cap's flow turns deviatoric near its top.)
std::pair<double, PlasticRegion> triaxial_peak(const GeneralizedCap& m, double pressure) {
    std::vector<double> state = initial_state(m);
    Voigt6 stress = consolidate(m, state, 2.0 * pressure + kMPa / 3.0);
    for (int i = 1; i <= 10; ++i) {
        Voigt6 zero = Voigt6::Zero();
        mixed_step(m, stress, state, zero, {true, true, true, false, false, false},
                   all_normal(-(2.0 * pressure + kMPa / 3.0) + (pressure + kMPa / 3.0) * i / 10.0));
    }
    double peak = 0.0;
    PlasticRegion region = PlasticRegion::elastic;
    Voigt6 increment = Voigt6::Zero();
    increment(0) = -2e-6;
    for (int i = 0; i < 200; ++i) {
        Voigt6 step = increment;
        region = mixed_step(m, stress, state, step, {false, true, true, false, false, false},
                            all_normal(-pressure));
        peak = std::max(peak, -stress(0));
    }
    return {peak, region};
}

TEST(CapTriaxial, PeakLiesOnTheFailureEnvelopeAtEveryConfiningPressure) {
    const cap::Parameters p = thesis_cap();
    const GeneralizedCap m(thesis_elastic(), p);
    for (double pressure : {0.01 * kMPa, 0.1 * kMPa, 1.0 * kMPa}) {
        // sigma_2 = sigma_3 = p: I1 = s1 + 2p and sqrt(J2) = (s1 - p) / sqrt(3); the peak
        // solves sqrt(J2) = k + theta I1 - gamma exp(-B1 I1).
        const double expected = solve_scalar(
            [&](double s1) {
                return (s1 - pressure) / std::sqrt(3.0) - envelope_of(p, s1 + 2.0 * pressure);
            },
            pressure, kMPa);
        const auto [peak, region] = triaxial_peak(m, pressure);
        EXPECT_TRUE(region == PlasticRegion::failure_surface || region == PlasticRegion::corner);
        // The return satisfies f1 = 0 to the 1e-14 solver tolerance; the lateral stress
        // control converges to 1e-11 of the stress; 1e-9 relative is safely above both.
        EXPECT_NEAR(peak, expected, 1e-9 * expected) << "p = " << pressure;
        RecordProperty("peak_error_at_kPa_" + std::to_string(static_cast<int>(pressure / 1e3)),
                       figure(std::abs(peak - expected) / expected));
    }
}

TEST(CapTriaxial, GammaZeroPeakIsTheDruckerPragerClosedForm) {
    cap::Parameters p = thesis_cap();
    p.gamma = 0.0;
    p.theta = 0.1;
    const GeneralizedCap m(thesis_elastic(), p);
    for (double pressure : {0.05 * kMPa, 0.5 * kMPa}) {
        // (s1 - p) / sqrt(3) = k + theta (s1 + 2p), linear in s1.
        const double r3 = 1.0 / std::sqrt(3.0);
        const double expected = (pressure * r3 + p.k + 2.0 * p.theta * pressure) / (r3 - p.theta);
        const auto [peak, region] = triaxial_peak(m, pressure);
        EXPECT_NEAR(peak, expected, 1e-9 * expected);
    }
}

/// Drained simple shear: normal stresses held at -p, gamma_xy prescribed.
TEST(CapShear, PlateauAtTheEnvelopeWithAssociatedDilatancyUntilTheCapArrives) {
    const cap::Parameters p = thesis_cap();
    const GeneralizedCap m(thesis_elastic(), p);
    std::vector<double> state = initial_state(m);
    Voigt6 stress = consolidate(m, state, 1.0 / 3.0 * kMPa); // X = 1 MPa, L ~ 0.87 MPa
    const double pressure = 0.2 * kMPa;                      // I1 = 0.6 MPa < L
    stress =
        drive(m, stress, state, hydrostatic_strain((0.6 * kMPa - 1.0 * kMPa) / (3.0 * kBulk)), 1);
    const double i1 = 3.0 * pressure;
    const double strength = envelope_of(p, i1);
    const double dilatancy = 3.0 * (p.theta + p.gamma * p.beta * std::exp(-p.beta * i1));
    Voigt6 increment = Voigt6::Zero();
    increment(3) = 1e-5;
    Voigt6 strain = Voigt6::Zero();
    int failure_steps = 0;
    int corner_steps = 0;
    double worst_ratio = 0.0;
    PlasticRegion previous = PlasticRegion::elastic;
    for (int i = 0; i < 2000; ++i) {
        const Voigt6 before = stress;
        std::vector<double> start = state;
        Voigt6 step = increment;
        const PlasticRegion region = mixed_step(
            m, stress, state, step, {true, true, true, false, false, false}, all_normal(-pressure));
        // Recover the strain increment the control found: elastic part from the stress change,
        // the rest plastic. Total volumetric strain change = d(tr eps).
        const Voigt6 d_eps = strain_for_stress(m, stress - before);
        const double dv_elastic = d_eps.head<3>().sum();
        const double dv_plastic = -(state[GeneralizedCap::kPlasticVolumetricStrain] -
                                    start[GeneralizedCap::kPlasticVolumetricStrain]);
        if (region == PlasticRegion::failure_surface && previous == region) {
            // Plateau: sqrt(J2) = F(I1); flow normal to f1 gives d(tr eps^p) / d(gamma^p) =
            // 3 F'(I1) > 0 (dilation, tension positive), with gamma^p = gamma on the plateau.
            EXPECT_NEAR(invariants(stress)[1], strength, 1e-9 * strength);
            EXPECT_LT(std::abs(dv_elastic), 1e-15);
            worst_ratio =
                std::max(worst_ratio, std::abs(dv_plastic / 1e-5 - dilatancy) / dilatancy);
            ++failure_steps;
        }
        if (region == PlasticRegion::corner && previous == region) {
            EXPECT_NEAR(invariants(stress)[1], strength, 1e-9 * strength);
            EXPECT_LT(std::abs(dv_plastic), 1e-15); // the cap stops the dilatancy
            ++corner_steps;
        }
        previous = region;
        strain += step;
    }
    EXPECT_GT(failure_steps, 10);
    EXPECT_GT(corner_steps, 10);
    // 3 F' from the closed form vs the recorded plastic strain: round-off of the 1e-9 strain
    // increments and the 1e-11 stress control, far below 1e-6.
    EXPECT_LT(worst_ratio, 1e-6);
    // At the end the cap has contracted onto the stress point: L = I1 and the recorded plastic
    // volumetric strain is the law's value at X = I1 + R F(I1).
    const double x_end = i1 + p.R * strength;
    EXPECT_NEAR(state[GeneralizedCap::kHardeningParameter], i1, 1e-9 * i1);
    EXPECT_NEAR(state[GeneralizedCap::kPlasticVolumetricStrain],
                p.W * (1.0 - std::exp(-p.D * (x_end - p.X0))), 1e-10);
    RecordProperty("dilatancy_ratio_error", figure(worst_ratio));
}

TEST(CapTension, ExtensionOfSandEndsAtTheApexWithZeroStress) {
    const GeneralizedCap m(thesis_elastic(), thesis_cap());
    std::vector<double> state = initial_state(m);
    Voigt6 stress = consolidate(m, state, 0.2 * kMPa);
    // Volumetric extension with a little distortion: the trial lies beyond the normal cone of
    // the failure surface at the apex, I1_tr < -9K F'(0) (q_tr - F(0)) / G.
    Voigt6 extension = hydrostatic_strain(-1e-3);
    extension(4) = 2e-6;
    Matrix6 tangent;
    EXPECT_EQ(m.update(extension, stress, state, &tangent), PlasticRegion::apex);
    // k = gamma puts the apex of the envelope at I1 = 0 = -T: cohesionless sand carries no
    // tension, every component is exactly 0, and so is the tangent.
    EXPECT_EQ(stress.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(tangent.cwiseAbs().maxCoeff(), 0.0);
}

TEST(CapTension, CutoffPlaneKeepsTheDeviatorAndItsCornerLimitsIt) {
    cap::Parameters p = thesis_cap();
    p.gamma = 0.0;
    p.theta = 0.1;
    p.tension = 0.01 * kMPa; // F(-T) = k - theta T = 0.03758 MPa > 0
    // F(0) = k > 0: with MAT_025's X0 = 0 the cap would close the domain to q = 0 (tested in
    // CapTension.ClampedCapLimitsTheCutoffToItsTop); a cap at 1 MPa leaves the cutoff alone.
    p.X0 = 1.0 * kMPa;
    const GeneralizedCap m(thesis_elastic(), p);
    const double f_cut = p.k - p.theta * p.tension;
    for (double shear : {0.0, 1e-6, 1e-5}) {
        std::vector<double> state = initial_state(m);
        Voigt6 stress = Voigt6::Zero();
        Voigt6 de = hydrostatic_strain(-1e-5);
        de(3) = shear;
        EXPECT_EQ(m.update(de, stress, state, nullptr), PlasticRegion::apex);
        const auto [i1, q] = invariants(stress);
        EXPECT_NEAR(i1, -p.tension, 1e-12 * p.tension);
        // Trial sqrt(J2) = G gamma: kept below F(-T) (the cutoff's flow is volumetric),
        // limited to F(-T) above it.
        EXPECT_NEAR(q, std::min(8.23e9 * shear, f_cut), 1e-12 * p.k);
    }
}

} // namespace
} // namespace grainload::materials::testing
