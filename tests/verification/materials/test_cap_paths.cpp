// Verification of the generalized cap model along laboratory paths with closed-form answers:
// conventional triaxial compression (peak on the failure envelope), drained simple shear
// (plateau, associated dilatancy until the cap reaches the stress point), and tension paths
// (apex and tension cutoff). Parameter sets of cap_test_support.hpp: the thesis section 7.2
// sand (F(0) = 0) and two whose envelope misses the origin (wagon, sand in ksi; MAT_025
// semantics, kappa0 < 0), unless noted.

#include "tests/unit/materials/cap_test_support.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

namespace grainload::materials::testing {
namespace {

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

/// The triaxial peak sigma_1 at confinement p: (s1 - p) / sqrt(3) = F(s1 + 2p), solved here.
double expected_peak(const cap::Parameters& p, double pressure, double scale) {
    return solve_scalar(
        [&](double s1) {
            return (s1 - pressure) / std::sqrt(3.0) - envelope_of(p, s1 + 2.0 * pressure);
        },
        pressure, scale);
}

/// Axial compression with the lateral stresses held at -p, on a sample consolidated to
/// 2p + scale/3 and unloaded to p, so that the cap centre L lies beyond the peak's I1 and the
/// path meets the failure surface itself; 200 axial steps reach 1.5 times the elastic strain
/// to the peak. Returns the largest axial compression reached and the last region. (A normally
/// consolidated sample rides the hardening cap and approaches the envelope only
/// asymptotically, as the cap's flow turns deviatoric near its top.)
std::pair<double, PlasticRegion> triaxial_peak(const GeneralizedCap& m, const CapSet& set,
                                               double pressure) {
    std::vector<double> state = initial_state(m);
    const double top = 2.0 * pressure + set.scale / 3.0;
    Voigt6 stress = consolidate(m, state, top);
    for (int i = 1; i <= 10; ++i) {
        Voigt6 zero = Voigt6::Zero();
        mixed_step(m, stress, state, zero, {true, true, true, false, false, false},
                   all_normal(-top + (top - pressure) * i / 10.0));
    }
    const double young = 9.0 * set.elastic.bulk_modulus * set.elastic.shear_modulus /
                         (3.0 * set.elastic.bulk_modulus + set.elastic.shear_modulus);
    const double to_peak = (expected_peak(set.p, pressure, set.scale) - pressure) / young;
    double peak = 0.0;
    PlasticRegion region = PlasticRegion::elastic;
    Voigt6 increment = Voigt6::Zero();
    increment(0) = -1.5 * to_peak / 200.0;
    for (int i = 0; i < 200; ++i) {
        Voigt6 step = increment;
        region = mixed_step(m, stress, state, step, {false, true, true, false, false, false},
                            all_normal(-pressure));
        peak = std::max(peak, -stress(0));
    }
    return {peak, region};
}

/// Confining pressures per set: from well below to above the envelope's scale.
std::vector<double> pressures(const CapSet& set) {
    return {0.01 * set.scale, 0.1 * set.scale, 1.0 * set.scale};
}

TEST(CapTriaxial, PeakLiesOnTheFailureEnvelopeAtEveryConfiningPressure) {
    for (const CapSet& set : cap_sets()) {
        const GeneralizedCap m(set.elastic, set.p);
        for (double pressure : pressures(set)) {
            const double expected = expected_peak(set.p, pressure, set.scale);
            const auto [peak, region] = triaxial_peak(m, set, pressure);
            EXPECT_TRUE(region == PlasticRegion::failure_surface || region == PlasticRegion::corner)
                << set.name;
            // The return satisfies f1 = 0 to the 1e-14 solver tolerance; the lateral stress
            // control converges to 1e-11 of the stress; 1e-9 relative is safely above both.
            EXPECT_NEAR(peak, expected, 1e-9 * expected) << set.name << " p = " << pressure;
            RecordProperty("peak_error_" + set.name + "_at_" +
                               std::to_string(std::lround(pressure / set.scale * 100)) +
                               "_percent_of_scale",
                           figure(std::abs(peak - expected) / expected));
        }
    }
}

TEST(CapTriaxial, GammaZeroPeakIsTheDruckerPragerClosedForm) {
    cap::Parameters p = thesis_cap();
    p.gamma = 0.0;
    p.theta = 0.1;
    const CapSet set{"dp", p, thesis_elastic(), 1.0 * kMPa};
    const GeneralizedCap m(thesis_elastic(), p);
    for (double pressure : {0.05 * kMPa, 0.5 * kMPa}) {
        // (s1 - p) / sqrt(3) = k + theta (s1 + 2p), linear in s1.
        const double r3 = 1.0 / std::sqrt(3.0);
        const double expected = (pressure * r3 + p.k + 2.0 * p.theta * pressure) / (r3 - p.theta);
        const auto [peak, region] = triaxial_peak(m, set, pressure);
        EXPECT_NEAR(peak, expected, 1e-9 * expected);
    }
}

/// Drained simple shear: normal stresses held at -p, gamma_xy prescribed.
TEST(CapShear, PlateauAtTheEnvelopeWithAssociatedDilatancyUntilTheCapArrives) {
    for (const CapSet& set : cap_sets()) {
        const cap::Parameters& p = set.p;
        const double bulk = set.elastic.bulk_modulus;
        const GeneralizedCap m(set.elastic, p);
        std::vector<double> state = initial_state(m);
        // Consolidated to X = scale, unloaded to I1 = 0.6 scale < L.
        Voigt6 stress = consolidate(m, state, set.scale / 3.0);
        stress = drive(m, stress, state, hydrostatic_strain(-0.4 * set.scale / (3.0 * bulk)), 1);
        const double pressure = 0.2 * set.scale;
        const double i1 = 3.0 * pressure;
        const double strength = envelope_of(p, i1);
        const double dilatancy = 3.0 * (p.theta + p.gamma * p.beta * std::exp(-p.beta * i1));
        // The dilatancy that brings the cap from X = scale onto the stress point, X = I1 +
        // R F(I1), at 3 F' per unit of plastic shear: cover it in about 500 steps.
        const auto law = [&](double x) { return p.W * (1.0 - std::exp(-p.D * (x - p.X0))); };
        const double needed = (law(set.scale) - law(i1 + p.R * strength)) / dilatancy;
        const double dgamma = needed / 500.0;
        Voigt6 increment = Voigt6::Zero();
        increment(3) = dgamma;
        int failure_steps = 0;
        int corner_steps = 0;
        double worst_ratio = 0.0;
        PlasticRegion previous = PlasticRegion::elastic;
        for (int i = 0; i < 2000 && corner_steps <= 10; ++i) {
            const Voigt6 before = stress;
            std::vector<double> start = state;
            Voigt6 step = increment;
            const PlasticRegion region =
                mixed_step(m, stress, state, step, {true, true, true, false, false, false},
                           all_normal(-pressure));
            // The elastic part of the volumetric strain from the stress change, the plastic
            // part recorded by the state.
            const double dv_elastic = strain_for_stress(m, stress - before).head<3>().sum();
            const double dv_plastic = -(state[GeneralizedCap::kPlasticVolumetricStrain] -
                                        start[GeneralizedCap::kPlasticVolumetricStrain]);
            if (region == PlasticRegion::failure_surface && previous == region) {
                // Plateau: sqrt(J2) = F(I1); flow normal to f1 gives d(tr eps^p) / d(gamma^p) =
                // 3 F'(I1) > 0 (dilation, tension positive), with gamma^p = gamma there.
                EXPECT_NEAR(invariants(stress)[1], strength, 1e-9 * strength) << set.name;
                EXPECT_LT(std::abs(dv_elastic), 1e-6 * dgamma) << set.name;
                worst_ratio =
                    std::max(worst_ratio, std::abs(dv_plastic / dgamma - dilatancy) / dilatancy);
                ++failure_steps;
            }
            if (region == PlasticRegion::corner && previous == region) {
                EXPECT_NEAR(invariants(stress)[1], strength, 1e-9 * strength) << set.name;
                EXPECT_LT(std::abs(dv_plastic), 1e-6 * dgamma) << set.name; // the cap stops it
                ++corner_steps;
            }
            previous = region;
        }
        EXPECT_GT(failure_steps, 10) << set.name;
        EXPECT_GT(corner_steps, 10) << set.name;
        // 3 F' from the closed form vs the recorded plastic strain: round-off of the strain
        // increments and the 1e-11 stress control, far below 1e-6.
        EXPECT_LT(worst_ratio, 1e-6) << set.name;
        // At the end the cap has contracted onto the stress point: kappa = L = I1 and the
        // recorded plastic volumetric strain is the law's value at X = I1 + R F(I1).
        const double x_end = i1 + p.R * strength;
        EXPECT_NEAR(state[GeneralizedCap::kHardeningParameter], i1, 1e-9 * i1) << set.name;
        EXPECT_NEAR(state[GeneralizedCap::kPlasticVolumetricStrain],
                    p.W * (1.0 - std::exp(-p.D * (x_end - p.X0))), 1e-10)
            << set.name;
        RecordProperty("dilatancy_ratio_error_" + set.name, figure(worst_ratio));
    }
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
