// The Mohr-Coulomb material in 3D: the strength at triaxial compression and extension and in
// plane strain against the closed-form Mohr-Coulomb limits (where each Drucker-Prager cone fit
// is right on one path only), the consistent tangent against finite differences in each region
// of the return, the flow rule's dilatancy, isotropy, and the reader's refusals.

#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "material_test_support.hpp"
#include "materials/cone_fit.hpp"
#include "materials/drucker_prager.hpp"
#include "materials/material_case_reader.hpp"
#include "materials/material_point_reader.hpp"
#include "materials/mohr_coulomb.hpp"
#include "materials/principal_stress.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <random>

namespace grainload::materials {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// A dense sand: phi 35 deg, psi 5 deg, a little cohesion so that the apex is not the origin.
const ElasticConstants kSand = ElasticConstants::from_young(1600.0, 50e6, 0.3);
constexpr MohrCoulomb::Parameters kParameters{35.0 * kDegree, 2e3, 5.0 * kDegree};

// The closed-form limit of the axial stress (tension positive) at confinement -p: triaxial
// compression (the axial stress the most compressive, s3) and extension (the least, s1) from
// (s1 - s3) + (s1 + s3) sin(phi) = 2 c cos(phi).
double compression_limit(double p, double phi, double c) {
    return -(p * (1.0 + std::sin(phi)) + 2.0 * c * std::cos(phi)) / (1.0 - std::sin(phi));
}
double extension_limit(double p, double phi, double c) {
    return (-p * (1.0 - std::sin(phi)) + 2.0 * c * std::cos(phi)) / (1.0 + std::sin(phi));
}

// A path with the Newton settings a driver file takes when it states none.
MaterialPointPath driver_file_path() {
    MaterialPointPath path;
    path.tolerance = io::default_value(kPathKeys, "tolerance");
    path.max_iterations = static_cast<int>(io::default_value(kPathKeys, "max_iterations"));
    return path;
}

// The final axial stress zz of a path that holds xx = yy = -p and strains zz by `axial` in 400
// steps.
double triaxial_limit(const Material& m, double p, double axial) {
    MaterialPointPath path = driver_file_path();
    path.initial_stress << -p, -p, -p, 0.0, 0.0, 0.0;
    PathSegment segment;
    segment.steps = 400;
    segment.stress_controlled = {true, true, false, false, false, false};
    segment.stress_target = path.initial_stress;
    segment.strain_increment(2) = axial;
    path.segments.push_back(segment);
    std::vector<MaterialPointRecord> records;
    drive_material_point(m, path, records);
    return records.back().stress(2);
}

TEST(MohrCoulomb, TriaxialCompressionAndExtensionReachTheHexagonWhereEachConeFitsOneOfThem) {
    const MohrCoulomb mc(kSand, kParameters);
    const auto cone = [&](ConeFit fit) {
        const ConeConstants k = fit_cone(fit, kParameters.friction_angle, kParameters.cohesion,
                                         kParameters.dilatancy_angle);
        return DruckerPrager(kSand, {k.alpha, k.k, k.alpha_flow});
    };
    const double p = 50e3;
    const double compression =
        compression_limit(p, kParameters.friction_angle, kParameters.cohesion);
    const double extension = extension_limit(p, kParameters.friction_angle, kParameters.cohesion);
    // 1e-9: the Newton tolerance of the driver (1e-10 of the stress) with room for round-off;
    // the limits are reached exactly by a perfectly plastic return.
    EXPECT_NEAR(triaxial_limit(mc, p, -0.02) / compression, 1.0, 1e-9);
    EXPECT_NEAR(triaxial_limit(mc, p, 0.02) / extension, 1.0, 1e-9);
    // The outer cone is right in compression and too strong in extension, the extension cone
    // the other way round: more than 5 % of the confinement apart.
    const DruckerPrager outer = cone(ConeFit::compression);
    const DruckerPrager inner_meridian = cone(ConeFit::extension);
    EXPECT_NEAR(triaxial_limit(outer, p, -0.02) / compression, 1.0, 1e-9);
    EXPECT_GT(std::abs(triaxial_limit(outer, p, 0.02) - extension), 0.05 * std::abs(p));
    EXPECT_NEAR(triaxial_limit(inner_meridian, p, 0.02) / extension, 1.0, 1e-9);
    EXPECT_GT(std::abs(triaxial_limit(inner_meridian, p, -0.02) - compression), 0.05 * std::abs(p));
}

// Plane strain, eps_zz = 0, xx held at -p, yy compressed: Mohr-Coulomb's limit does not depend
// on the intermediate stress zz, so it is the compression formula; the associated plane-strain
// cone fit gives the same collapse stress (de Souza Neto et al. 2008, section 6.4.2), a second
// method for the same number.
TEST(MohrCoulomb, PlaneStrainLimitIsTheMohrCoulombOneAndTheAssociatedPlaneStrainConeAgrees) {
    const MohrCoulomb::Parameters associated{35.0 * kDegree, 2e3, 35.0 * kDegree};
    const MohrCoulomb mc(kSand, associated);
    const ConeConstants k = fit_cone(ConeFit::plane_strain, associated.friction_angle,
                                     associated.cohesion, associated.dilatancy_angle);
    const DruckerPrager cone(kSand, {k.alpha, k.k, k.alpha_flow});
    const double p = 50e3;
    const auto limit = [&](const Material& m) {
        MaterialPointPath path = driver_file_path();
        path.initial_stress << -p, -p, -p, 0.0, 0.0, 0.0;
        PathSegment segment;
        segment.steps = 400;
        segment.stress_controlled = {true, false, false, false, false, false};
        segment.stress_target = path.initial_stress;
        segment.strain_increment(1) = -0.02;
        path.segments.push_back(segment);
        std::vector<MaterialPointRecord> records;
        drive_material_point(m, path, records);
        return records.back().stress(1);
    };
    const double expected = compression_limit(p, associated.friction_angle, associated.cohesion);
    EXPECT_NEAR(limit(mc) / expected, 1.0, 1e-9);
    // The cone reaches its limit asymptotically (its flow is not plane in the deviatoric plane
    // until sigma_zz settles): 1e-4 after a strain of 50 times the yield strain.
    EXPECT_NEAR(limit(cone) / expected, 1.0, 1e-4);
}

// The trial's principal stresses (tension positive) placed in a rotated frame, so that the
// spectral decomposition and the rotation back are part of what is checked.
Voigt6 rotated(double s1, double s2, double s3) {
    const Mat3 q = Eigen::AngleAxisd(0.4, Vec3(1.0, 2.0, 0.5).normalized()).toRotationMatrix();
    return from_principal(Vec3(s1, s2, s3), q);
}

struct RegionCase {
    const char* name;
    Voigt6 stress;
    Voigt6 increment;
    PlasticRegion region;
};

TEST(MohrCoulomb, ConsistentTangentMatchesFiniteDifferencesInEveryRegion) {
    const MohrCoulomb mc(kSand, kParameters);
    const Matrix6 elastic = kSand.stiffness();
    const Mat3 q = Eigen::AngleAxisd(0.4, Vec3(1.0, 2.0, 0.5).normalized()).toRotationMatrix();
    const auto strain = [&](double e1, double e2, double e3) {
        Voigt6 e = from_principal(Vec3(e1, e2, e3), q);
        e.tail<3>() *= 2.0; // engineering shear
        return e;
    };
    // Start at -100 kPa and strain so that the trial lies in each region in turn: a small
    // step (elastic), a deviatoric one with distinct principal strains (plane), two equal
    // principal strains either way (the compression and extension corners), a dilation (apex).
    const Voigt6 start = rotated(-100e3, -100e3, -100e3);
    const std::vector<RegionCase> cases{
        {"elastic", start, strain(1e-5, 0.0, -1e-5), PlasticRegion::elastic},
        {"plane", start, strain(3e-3, 0.5e-3, -3e-3), PlasticRegion::failure_surface},
        {"compression corner", start, strain(2e-3, 2e-3, -4e-3), PlasticRegion::corner},
        {"extension corner", start, strain(4e-3, -2e-3, -2e-3), PlasticRegion::corner},
        {"apex", start, strain(5e-3, 4e-3, 3e-3), PlasticRegion::apex},
    };
    for (const RegionCase& c : cases) {
        // The corners' trials sit exactly on a meridian; nudge them off it so that the finite
        // differences stay on one side of it, as the analytic tangent does.
        Voigt6 increment = c.increment;
        increment(0) += 1e-9;
        Voigt6 stress = c.stress;
        std::vector<double> state = testing::initial_state(mc);
        Matrix6 tangent;
        EXPECT_EQ(mc.update(increment, stress, state, &tangent), c.region) << c.name;
        const Matrix6 fd = testing::finite_difference_tangent(
            mc, c.stress, testing::initial_state(mc), increment, 1e-10);
        // 1e-5 of the elastic stiffness: central differences with h = 1e-10 against strains of
        // 1e-3 (truncation 1e-14) and stresses of 1e5 Pa (round-off 1e-11 / 1e-10 of E).
        EXPECT_LT(testing::relative_tangent_error(tangent, fd, elastic), 1e-5) << c.name;
    }
}

TEST(MohrCoulomb, ReturnedStressLiesOnTheHexagonAndFlowsWithTheDilatancyAngle) {
    const MohrCoulomb mc(kSand, kParameters);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> e(-4e-3, 4e-3);
    int plane_returns = 0;
    for (int trial = 0; trial < 200; ++trial) {
        Voigt6 increment;
        for (int i = 0; i < 6; ++i) {
            increment(i) = e(random);
        }
        increment.head<3>().array() -= 2e-3; // mostly compressive
        Voigt6 stress = rotated(-80e3, -100e3, -120e3);
        std::vector<double> state = testing::initial_state(mc);
        const PlasticRegion region = mc.update(increment, stress, state, nullptr);
        const Vec3 s = principal_stresses(stress).values;
        // On or inside the hexagon to round-off (1e-9 of the stress level).
        const double scale = 1e-9 * (s.cwiseAbs().maxCoeff() + mc.surface().apex());
        EXPECT_LE(mc.yield_function(stress), scale);
        if (region == PlasticRegion::elastic) {
            continue;
        }
        EXPECT_NEAR(mc.yield_function(stress), 0.0, scale);
        if (region != PlasticRegion::failure_surface) {
            continue;
        }
        ++plane_returns;
        // On a plane the plastic strain is dg (1 + sin psi, 0, -(1 - sin psi)): volumetric
        // 2 dg sin psi against the principal difference 2 dg.
        const double ep_shear = state[0];
        const double ep_volume = state[1];
        const double sin_psi = std::sin(kParameters.dilatancy_angle);
        // sqrt(2/3)||dev e_p|| of that vector is dg sqrt(2/3) sqrt(2 + 2 sin^2 psi / 3).
        const double dg = ep_volume / (2.0 * sin_psi);
        EXPECT_NEAR(ep_shear / (dg * std::sqrt(2.0 / 3.0 * (2.0 + 2.0 * sin_psi * sin_psi / 3.0))),
                    1.0, 1e-9);
    }
    EXPECT_GT(plane_returns, 20);
}

TEST(MohrCoulomb, UpdateIsIsotropic) {
    const MohrCoulomb mc(kSand, kParameters);
    const Voigt6 stress = rotated(-60e3, -90e3, -150e3);
    Voigt6 increment;
    increment << 1e-3, -2e-3, 3e-4, 2e-3, -1e-3, 5e-4;
    const Mat3 r = Eigen::AngleAxisd(1.1, Vec3(0.3, -1.0, 0.7).normalized()).toRotationMatrix();
    const auto rotate = [&](const Voigt6& v, bool engineering) {
        Voigt6 t = v;
        if (engineering) {
            t.tail<3>() *= 0.5;
        }
        const Mat3 m = r * testing::stress_tensor(t) * r.transpose();
        Voigt6 out;
        out << m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(1, 2), m(2, 0);
        if (engineering) {
            out.tail<3>() *= 2.0;
        }
        return out;
    };
    Voigt6 a = stress;
    Voigt6 b = rotate(stress, false);
    std::vector<double> sa = testing::initial_state(mc);
    std::vector<double> sb = testing::initial_state(mc);
    EXPECT_NE(mc.update(increment, a, sa, nullptr), PlasticRegion::elastic);
    mc.update(rotate(increment, true), b, sb, nullptr);
    // 1e-9 of the stress: the two decompositions differ in round-off only.
    EXPECT_LT((rotate(a, false) - b).cwiseAbs().maxCoeff(), 1e-9 * 150e3);
    EXPECT_NEAR(sa[0], sb[0], 1e-12);
}

TEST(MohrCoulomb, CohesionlessTensionReturnsToZeroStress) {
    const MohrCoulomb mc(kSand, {30.0 * kDegree, 0.0, 0.0});
    Voigt6 stress = rotated(-1e3, -2e3, -3e3);
    Voigt6 increment;
    increment << 1e-3, 2e-3, 1e-3, 0.0, 1e-4, 0.0;
    std::vector<double> state = testing::initial_state(mc);
    EXPECT_EQ(mc.update(increment, stress, state, nullptr), PlasticRegion::apex);
    EXPECT_EQ(stress.cwiseAbs().maxCoeff(), 0.0);
}

std::unique_ptr<Material> build(const std::string& keys) {
    const auto document = io::CaseDocument::from_string(
        "[[material]]\nmodel = \"mohr_coulomb\"\ndensity = \"1600 kg/m^3\"\n"
        "youngs_modulus = \"50 MPa\"\npoisson_ratio = 0.3\n" +
            keys,
        "case.toml");
    auto material = read_material(document->root().array_of_tables("material").front());
    document->reject_unknown_keys();
    return material;
}

TEST(MohrCoulomb, ReadsItsKeysAndRefusesAnglesOutOfRange) {
    const auto m = build("friction_angle = \"35 deg\"\ncohesion = \"2 kPa\"\n"
                         "dilatancy_angle = \"5 deg\"\n");
    ASSERT_EQ(m->model(), "mohr_coulomb");
    const auto& mc = dynamic_cast<const MohrCoulomb&>(*m);
    EXPECT_DOUBLE_EQ(mc.parameters().friction_angle, 35.0 * kDegree);
    EXPECT_DOUBLE_EQ(mc.parameters().cohesion, 2e3);
    EXPECT_THROW(build("friction_angle = \"0 deg\"\ncohesion = \"0 kPa\"\n"
                       "dilatancy_angle = \"0 deg\"\n"),
                 io::CaseError);
    EXPECT_THROW(build("friction_angle = \"30 deg\"\ncohesion = \"0 kPa\"\n"
                       "dilatancy_angle = \"31 deg\"\n"),
                 io::CaseError);
    EXPECT_THROW(build("friction_angle = \"30 deg\"\ncohesion = \"0 kPa\"\n"
                       "dilatancy_angle = \"0 deg\"\ncone_fit = \"compression\"\n"),
                 io::CaseError);
}

} // namespace
} // namespace grainload::materials
