// Verification: Drucker-Prager along laboratory paths run by the material-point driver, against
// closed forms: triaxial compression peak (Mohr-Coulomb, which the compression cone matches),
// plane-strain limit (Mohr-Coulomb in the plane, plane-strain cone), pure-shear plateau
// (psi = 0) and dilatancy sign (associated), hydrostatic compression and extension to the apex.

#include "materials/voigt_algebra.hpp"
#include "support/test_folder.hpp"
#include "tests/unit/materials/material_test_support.hpp"
#include "tests/verification/materials/driver_support.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <string>
#include <vector>

namespace grainload::materials {
namespace {

constexpr double kPhi = 30.0 * std::numbers::pi / 180.0;
constexpr double kCohesion = 10e3;

std::string sand(const std::string& fit, double psi_deg) {
    return R"(
[[material]]
model = "drucker_prager"
density = "1700 kg/m^3"
youngs_modulus = "50 MPa"
poisson_ratio = 0.3
friction_angle = "30 deg"
cohesion = "10 kPa"
dilatancy_angle = ")" +
           std::to_string(psi_deg) + R"( deg"
cone_fit = ")" +
           fit + "\"\n";
}

std::string kpa(double value) {
    return "\"" + std::to_string(value / 1e3) + " kPa\"";
}

TEST(DruckerPragerTriaxial, PeakMatchesMohrCoulombAtSeveralConfinements) {
    for (double p : {50e3, 100e3, 200e3}) {
        const std::string lateral = kpa(-p);
        const auto run = testing::run_driver_text(
            sand("compression", 5.0) + "[path]\ninitial_stress = \"" + std::to_string(-p / 1e3) +
            " " + std::to_string(-p / 1e3) + " " + std::to_string(-p / 1e3) +
            " 0 0 0 kPa\"\n[[path.segment]]\nsteps = 100\n" +
            "strain_increment = { xx = -0.03 }\nstress = { yy = " + lateral + ", zz = " + lateral +
            " }\n");
        // Mohr-Coulomb: sigma_1 - sigma_3 = (2 c cos + 2 p sin) / (1 - sin) in compression.
        const double exact =
            (2.0 * kCohesion * std::cos(kPhi) + 2.0 * p * std::sin(kPhi)) / (1.0 - std::sin(kPhi));
        double peak = 0.0;
        for (const auto& r : run.records) {
            peak = std::max(peak, r.stress(1) - r.stress(0));
        }
        // Perfect plasticity: the plateau is the surface itself, reached to the Newton
        // tolerance (1e-10 of the stress): 1e-8 relative.
        EXPECT_NEAR(peak, exact, 1e-8 * exact) << "p = " << p;
        EXPECT_EQ(run.records.back().region, PlasticRegion::failure_surface);
        ::testing::Test::RecordProperty("triaxial_peak_rel_error_p" + testing::figure(p),
                                        testing::figure(std::abs(peak - exact) / exact));
    }
}

TEST(DruckerPragerPlaneStrain, LimitStateMatchesMohrCoulombInThePlane) {
    const double p = 100e3;
    for (double psi : {0.0, 30.0}) {
        const auto run = testing::run_driver_text(
            sand("plane_strain", psi) +
            "[path]\ninitial_stress = \"-100 -100 -100 0 0 0 kPa\"\n[[path.segment]]\n" +
            "steps = 400\nstrain_increment = { xx = -0.08 }\nstress = { yy = " + kpa(-p) + " }\n");
        const Voigt6& s = run.records.back().stress;
        // In-plane Mohr-Coulomb with compression-positive s1 = -sigma_xx, s3 = -sigma_yy.
        const double s1 = -s(0);
        const double s3 = -s(1);
        const double mismatch =
            (s1 - s3) - (2.0 * kCohesion * std::cos(kPhi) + (s1 + s3) * std::sin(kPhi));
        // The limit is approached as eps_zz^p -> 0 (exponentially in the axial strain); after
        // 8 % strain (80 yield strains) it is converged to 1e-8 of the deviator.
        EXPECT_LT(std::abs(mismatch), 1e-8 * (s1 - s3)) << "psi = " << psi;
        ::testing::Test::RecordProperty("plane_strain_rel_mismatch_psi" + testing::figure(psi),
                                        testing::figure(std::abs(mismatch) / (s1 - s3)));
    }
}

std::string thesis_sand(double theta_flow) {
    return R"(
[[material]]
model = "drucker_prager"
density = "2099 kg/m^3"
bulk_modulus = "30.62 MPa"
shear_modulus = "8.23 MPa"
dp_k = "0.03858 MPa"
dp_theta = 0.03
dp_theta_flow = )" +
           std::to_string(theta_flow) + "\n";
}

constexpr double kK = 0.03858e6;
constexpr double kTheta = 0.03;

TEST(DruckerPragerPureShear, PlateauAtTheEnvelopeWithoutDilatancy) {
    const double p0 = 200e3;
    const auto run = testing::run_driver_text(
        thesis_sand(0.0) + "[path]\ninitial_stress = \"-200 -200 -200 0 0 0 kPa\"\n" +
        "[[path.segment]]\nsteps = 50\nstrain_increment = { xy = 0.05 }\n");
    const MaterialPointRecord& last = run.records.back();
    // psi = 0: isochoric flow keeps I1 = -3 p0, so tau = sqrt(J2) = k + 3 theta p0 exactly.
    const double plateau = kK + 3.0 * kTheta * p0;
    EXPECT_NEAR(last.stress(3), plateau, 1e-10 * plateau);
    EXPECT_NEAR(voigt::trace(last.stress), -3.0 * p0, 1e-10 * p0);
    EXPECT_NEAR(last.state[1], 0.0, 1e-15);
}

TEST(DruckerPragerPureShear, AssociatedFlowDilatesAndHardensUnderConstraint) {
    const auto run = testing::run_driver_text(
        thesis_sand(kTheta) + "[path]\ninitial_stress = \"-200 -200 -200 0 0 0 kPa\"\n" +
        "[[path.segment]]\nsteps = 50\nstrain_increment = { xy = 0.05 }\n");
    const MaterialPointRecord& last = run.records.back();
    // Tension positive: dilatancy is a positive plastic volumetric strain; with the total volume
    // held the mean stress becomes more compressive and tau keeps rising along the envelope.
    EXPECT_GT(last.state[1], 0.0);
    EXPECT_LT(voigt::trace(last.stress), -600e3);
    EXPECT_GT(last.stress(3), kK + 3.0 * kTheta * 200e3);
    EXPECT_NEAR(last.stress(3), kK - kTheta * voigt::trace(last.stress), 1e-10 * kK);
}

TEST(DruckerPragerHydrostatic, CompressionIsElasticAndExtensionStopsAtTheApex) {
    const double bulk = 30.62e6;
    for (int steps : {1, 10, 1000}) {
        const std::string n = std::to_string(steps);
        const auto run = testing::run_driver_text(
            thesis_sand(kTheta) + "[path]\n[[path.segment]]\nsteps = " + n +
            "\nstrain_increment = { xx = -0.002, yy = -0.002, zz = -0.002 }\n" +
            "[[path.segment]]\nsteps = " + n +
            "\nstrain_increment = { xx = 0.008, yy = 0.008, zz = 0.008 }\n");
        const auto& compressed = run.records[static_cast<std::size_t>(steps)];
        // Elastic compression: I1 = 3 K eps_v (round-off only).
        EXPECT_NEAR(voigt::trace(compressed.stress), 3.0 * bulk * -0.006, 1e-10 * bulk * 0.018);
        const auto& last = run.records.back();
        // Extension ends at the apex I1 = k / theta with eps_v^p = eps_v - I1 / (3K), the same
        // for 1, 10 and 1000 steps to 1e-8 relative (the required step independence).
        const double apex = kK / kTheta;
        EXPECT_NEAR(voigt::trace(last.stress), apex, 1e-8 * apex) << steps;
        EXPECT_NEAR(last.state[1], 0.018 - apex / (3.0 * bulk), 1e-8 * 0.018) << steps;
        EXPECT_EQ(last.region, PlasticRegion::apex);
    }
}

TEST(MatpointCases, ExampleDriversRunAndTriaxialPeakIsMohrCoulomb) {
    const std::string dir = std::string(GRAINLOAD_SOURCE_DIR) + "/cases/matpoint/";
    for (const char* name : {"triaxial_dp", "hydrostatic_dp", "uniaxial_vm_cycle", "triaxial_cap",
                             "hydrostatic_cap", "oedometer_cap_wagon", "triaxial_mc"}) {
        std::vector<std::string> notices;
        EXPECT_EQ(run_material_point(dir + name + ".toml",
                                     grainload::testing::process_folder() + name + ".csv", notices),
                  0)
            << name;
    }
    const auto run = testing::run_driver_file(dir + "triaxial_dp.toml");
    double peak = 0.0;
    for (const auto& r : run.records) {
        peak = std::max(peak, r.stress(1) - r.stress(0));
    }
    const double exact =
        (2.0 * kCohesion * std::cos(kPhi) + 2.0 * 100e3 * std::sin(kPhi)) / (1.0 - std::sin(kPhi));
    EXPECT_NEAR(peak, exact, 1e-8 * exact);
}

// The Mohr-Coulomb driver reaches both of the hexagon's closed-form limits on one path: the
// compression peak of triaxial_dp.toml's cone and, after it, the extension limit that no
// compression cone has (1e-8: the driver's Newton tolerance, 1e-10 of the stress, with room).
TEST(MatpointCases, MohrCoulombDriverReachesTheCompressionAndExtensionLimits) {
    const auto run = testing::run_driver_file(std::string(GRAINLOAD_SOURCE_DIR) +
                                              "/cases/matpoint/triaxial_mc.toml");
    double peak = 0.0;
    for (const auto& r : run.records) {
        peak = std::max(peak, r.stress(1) - r.stress(0));
    }
    const double s = std::sin(kPhi);
    const double compression = (2.0 * kCohesion * std::cos(kPhi) + 2.0 * 100e3 * s) / (1.0 - s);
    EXPECT_NEAR(peak, compression, 1e-8 * compression);
    const double extension = (-100e3 * (1.0 - s) + 2.0 * kCohesion * std::cos(kPhi)) / (1.0 + s);
    EXPECT_NEAR(run.records.back().stress(0), extension, 1e-8 * 100e3);
}

} // namespace
} // namespace grainload::materials
