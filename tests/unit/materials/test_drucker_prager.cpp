#include "materials/cone_fit.hpp"
#include "materials/drucker_prager.hpp"
#include "materials/voigt_algebra.hpp"
#include "tests/unit/materials/material_test_support.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace grainload::materials {
namespace {

using testing::initial_state;

// A stiff sand, SI: K = 50 MPa, G = 30 MPa; k = 20 kPa, alpha = 0.25 (apex at I1 = 80 kPa),
// alpha_flow = 0.1 (non-associated); cutoff T = 20 kPa below the apex unless stated.
const ElasticConstants kSand = ElasticConstants::from_bulk_shear(2000.0, 50e6, 30e6);
constexpr double kK = 20e3;
constexpr double kAlpha = 0.25;
constexpr double kAlphaFlow = 0.1;
constexpr double kCutoff = 20e3;

DruckerPrager sand(double cutoff = kCutoff, double alpha_flow = kAlphaFlow) {
    return DruckerPrager(kSand, {kAlpha, kK, alpha_flow, cutoff});
}

/// Unit deviatoric direction (||n|| = 1) mixing normal and shear components.
Voigt6 direction() {
    Voigt6 n;
    n << 1.0, -0.4, -0.6, 0.5, -0.2, 0.3;
    n = voigt::deviator(n);
    return n / voigt::norm(n);
}

/// Strain increment from zero stress whose trial stress has invariants (I1, sqrt(J2)).
Voigt6 trial_strain(double i1, double sqrt_j2) {
    const Voigt6 trial = std::sqrt(2.0) * sqrt_j2 * direction() + (i1 / 3.0) * voigt::identity();
    return kSand.stiffness().fullPivLu().solve(trial);
}

struct Result {
    Voigt6 stress;
    std::vector<double> state;
    PlasticRegion region;
    Matrix6 tangent;
};

Result update_from_zero(const DruckerPrager& m, const Voigt6& de) {
    Result r{Voigt6::Zero(), initial_state(m), PlasticRegion::elastic, Matrix6::Zero()};
    r.region = m.update(de, r.stress, r.state, &r.tangent);
    return r;
}

double sqrt_j2(const Voigt6& s) {
    return voigt::norm(voigt::deviator(s)) / std::sqrt(2.0);
}

TEST(ConeFit, CompressionAndExtensionConesMatchMohrCoulombOnTheirMeridians) {
    // Mohr-Coulomb (compression positive principal stresses): s1 - s3 = 2c cos(phi) +
    // (s1 + s3) sin(phi). Each cone must pass through the hexagon on its meridian.
    const double phi = 32.0 * std::numbers::pi / 180.0;
    const double c = 15e3;
    const double p3 = 100e3; // the smaller principal pressure
    const double q = (2.0 * c * std::cos(phi) + 2.0 * p3 * std::sin(phi)) / (1.0 - std::sin(phi));
    // Triaxial compression: pressures (p3 + q, p3, p3); sqrt(J2) = q / sqrt3.
    const ConeConstants comp = fit_cone(ConeFit::compression, phi, c, phi);
    EXPECT_NEAR(q / std::sqrt(3.0) - comp.alpha * (3.0 * p3 + q) - comp.k, 0.0, 1e-10 * c);
    // Triaxial extension: pressures (p3 + q, p3 + q, p3), the same Mohr circle.
    const ConeConstants ext = fit_cone(ConeFit::extension, phi, c, phi);
    EXPECT_NEAR(q / std::sqrt(3.0) - ext.alpha * (3.0 * p3 + 2.0 * q) - ext.k, 0.0, 1e-10 * c);
    // Associated flow: the potential is the yield function.
    EXPECT_DOUBLE_EQ(comp.alpha_flow, comp.alpha);
    EXPECT_DOUBLE_EQ(ext.alpha_flow, ext.alpha);
}

TEST(ConeFit, PlaneStrainFitReducesToKnownLimits) {
    const double phi = 30.0 * std::numbers::pi / 180.0;
    const double c = 10e3;
    // psi = phi: de Souza Neto eq. 6.123 (3 tan / sqrt(9 + 12 tan^2) on p), which is also the
    // inscribed cone: both written independently here.
    const double t = std::tan(phi);
    const ConeConstants assoc = fit_cone(ConeFit::plane_strain, phi, c, phi);
    EXPECT_NEAR(assoc.alpha, t / std::sqrt(9.0 + 12.0 * t * t), 1e-15);
    EXPECT_NEAR(assoc.k, 3.0 * c / std::sqrt(9.0 + 12.0 * t * t), 1e-10);
    const ConeConstants inner = fit_cone(ConeFit::inner, phi, c, phi);
    EXPECT_NEAR(inner.alpha, assoc.alpha, 1e-15);
    EXPECT_NEAR(inner.k, assoc.k, 1e-10);
    // psi = 0: alpha = sin(phi) / 3, k = c cos(phi), no dilatancy.
    const ConeConstants zero = fit_cone(ConeFit::plane_strain, phi, c, 0.0);
    EXPECT_NEAR(zero.alpha, std::sin(phi) / 3.0, 1e-15);
    EXPECT_NEAR(zero.k, c * std::cos(phi), 1e-10);
    EXPECT_EQ(zero.alpha_flow, 0.0);
    // Cones ordered at any pressure: compression outermost, inner innermost.
    const ConeConstants comp = fit_cone(ConeFit::compression, phi, c, phi);
    const ConeConstants ext = fit_cone(ConeFit::extension, phi, c, phi);
    const auto strength = [](const ConeConstants& f) { return f.k + f.alpha * 300e3; };
    EXPECT_GT(strength(comp), strength(ext));
    EXPECT_GT(strength(ext), strength(inner));
}

TEST(DruckerPrager, ElasticTrialOnTheSurfaceStaysElastic) {
    const DruckerPrager m = sand();
    const double i1 = -60e3;
    const Result r = update_from_zero(m, trial_strain(i1, kK - kAlpha * i1));
    EXPECT_EQ(r.region, PlasticRegion::elastic);
    EXPECT_NEAR(m.yield_function(r.stress), 0.0, 1e-10 * kK);
}

TEST(DruckerPrager, ConeReturnSatisfiesYieldAndFlowRule) {
    const DruckerPrager m = sand();
    const Voigt6 de = trial_strain(-60e3, 60e3);
    const Result r = update_from_zero(m, de);
    ASSERT_EQ(r.region, PlasticRegion::failure_surface);
    // f = 0 to round-off (closed-form multiplier), 1e-10 relative to k.
    EXPECT_NEAR(m.yield_function(r.stress), 0.0, 1e-10 * kK);
    // Plastic strain = D_e^-1 (sigma_trial - sigma) must have tr / (sqrt2 ||e_p||) = 3 alpha_flow
    // and a deviator along the trial direction.
    const Voigt6 trial = kSand.stiffness() * de;
    const Voigt6 plastic =
        voigt::tensor_from_engineering(kSand.stiffness().fullPivLu().solve(trial - r.stress));
    const Voigt6 dev = voigt::deviator(plastic);
    EXPECT_NEAR(voigt::trace(plastic) / (std::sqrt(2.0) * voigt::norm(dev)), 3.0 * kAlphaFlow,
                1e-10);
    EXPECT_LT((dev / voigt::norm(dev) - direction()).norm(), 1e-10);
    EXPECT_NEAR(r.state[1], voigt::trace(plastic), 1e-14);
}

TEST(DruckerPrager, CutoffAndCornerReturns) {
    const DruckerPrager m = sand();
    // Cutoff face: I1 > T and sqrt(J2) below the corner value k - alpha T = 15 kPa.
    const Result face = update_from_zero(m, trial_strain(40e3, 5e3));
    ASSERT_EQ(face.region, PlasticRegion::apex);
    EXPECT_NEAR(voigt::trace(face.stress), kCutoff, 1e-10 * kCutoff);
    EXPECT_NEAR(sqrt_j2(face.stress), 5e3, 1e-10 * kK);
    // Corner: far out in tension and shear.
    const Result corner = update_from_zero(m, trial_strain(80e3, 30e3));
    ASSERT_EQ(corner.region, PlasticRegion::apex);
    EXPECT_NEAR(voigt::trace(corner.stress), kCutoff, 1e-10 * kCutoff);
    EXPECT_NEAR(sqrt_j2(corner.stress), kK - kAlpha * kCutoff, 1e-10 * kK);
    // Apex (default cutoff): any trial beyond the cone's apex normal returns to I1 = k / alpha.
    const DruckerPrager apex_model = sand(std::numeric_limits<double>::infinity());
    const Result apex = update_from_zero(apex_model, trial_strain(150e3, 5e3));
    ASSERT_EQ(apex.region, PlasticRegion::apex);
    EXPECT_LT((apex.stress - (kK / kAlpha / 3.0) * voigt::identity()).norm(), 1e-10 * kK);
    EXPECT_NEAR(apex.state[1], (150e3 - kK / kAlpha) / (3.0 * kSand.bulk_modulus), 1e-14);
}

/// Stress after a trial at (I1, sqrt(J2)); used to probe continuity across region boundaries.
Voigt6 returned(const DruckerPrager& m, double i1, double sj) {
    return update_from_zero(m, trial_strain(i1, sj)).stress;
}

TEST(DruckerPrager, ReturnIsContinuousAcrossRegionBoundaries) {
    const double bulk = kSand.bulk_modulus;
    const double shear = kSand.shear_modulus;
    const double corner_sj = kK - kAlpha * kCutoff;
    const double delta = 1e-3; // Pa: a Lipschitz return moves by O(delta), far below 1 Pa
    const auto check = [&](const DruckerPrager& m, double i1, double sj, double di1, double dsj) {
        const Voigt6 on = returned(m, i1, sj);
        const Voigt6 before = returned(m, i1 - di1 * delta, sj - dsj * delta);
        const Voigt6 after = returned(m, i1 + di1 * delta, sj + dsj * delta);
        EXPECT_LT((before - on).norm(), 10.0 * delta) << i1 << ' ' << sj;
        EXPECT_LT((after - on).norm(), 10.0 * delta) << i1 << ' ' << sj;
    };
    const DruckerPrager m = sand();
    // Cone | corner: the ray from the corner along the cone's return direction (9K af, G).
    const double t = 3.0;
    check(m, kCutoff + 9.0 * bulk * kAlphaFlow * t, corner_sj + shear * t, 1.0, 0.0);
    // Cutoff face | corner: the horizontal sqrt(J2) = k - alpha T, I1 > T.
    check(m, 3.0 * kCutoff, corner_sj, 0.0, 1.0);
    // Elastic | cone and elastic | cutoff.
    check(m, -40e3, kK + kAlpha * 40e3, 0.0, 1.0);
    check(m, kCutoff, 2e3, 1.0, 0.0);
    // Cone | apex with the default cutoff.
    const DruckerPrager a = sand(std::numeric_limits<double>::infinity());
    check(a, kK / kAlpha + 9.0 * bulk * kAlphaFlow * t, shear * t, 1.0, 0.0);
}

TEST(DruckerPrager, ConsistentTangentMatchesFiniteDifferenceInEveryRegion) {
    struct Case {
        const char* name;
        double cutoff;
        double alpha_flow;
        double i1;
        double sj;
        PlasticRegion region;
    };
    const double inf = std::numeric_limits<double>::infinity();
    const Case cases[] = {
        {"elastic", kCutoff, kAlphaFlow, -30e3, 5e3, PlasticRegion::elastic},
        {"cone_nonassociated", kCutoff, kAlphaFlow, -60e3, 60e3, PlasticRegion::failure_surface},
        {"cone_associated", kCutoff, kAlpha, -60e3, 60e3, PlasticRegion::failure_surface},
        {"cutoff_face", kCutoff, kAlphaFlow, 40e3, 5e3, PlasticRegion::apex},
        {"corner", kCutoff, kAlphaFlow, 80e3, 30e3, PlasticRegion::apex},
        {"apex", inf, kAlphaFlow, 150e3, 5e3, PlasticRegion::apex},
    };
    for (const Case& c : cases) {
        const DruckerPrager m = sand(c.cutoff, c.alpha_flow);
        const Voigt6 de = trial_strain(c.i1, c.sj);
        const Result r = update_from_zero(m, de);
        ASSERT_EQ(r.region, c.region) << c.name;
        // h = 1e-9 against strains of ~1e-3 keeps every probe inside one region; the error
        // is then round-off (~1e-16 sigma / h), far below 1e-5 of the elastic stiffness.
        const Matrix6 fd =
            testing::finite_difference_tangent(m, Voigt6::Zero(), initial_state(m), de, 1e-9);
        const double error = testing::relative_tangent_error(r.tangent, fd, kSand.stiffness());
        EXPECT_LT(error, 1e-5) << c.name;
        RecordProperty(std::string("fd_tangent_error_") + c.name, testing::figure(error));
    }
}

TEST(DruckerPrager, RotatedStrainPathRotatesTheStress) {
    const DruckerPrager m = sand(kCutoff, kAlpha);
    const Mat3 r = testing::some_rotation();
    Voigt6 a = -30e3 * voigt::identity();
    Voigt6 b = a;
    auto sa = initial_state(m);
    auto sb = initial_state(m);
    const Voigt6 de = trial_strain(-10e3, 20e3);
    for (int i = 0; i < 8; ++i) {
        const Voigt6 step = i < 4 ? de : Voigt6(-0.8 * de);
        m.update(step, a, sa, nullptr);
        m.update(testing::rotate_strain(r, step), b, sb, nullptr);
    }
    // Isotropy: equal up to the round-off of the rotations, 1e-12 relative.
    EXPECT_LT((testing::rotate_stress(r, a) - b).norm(), 1e-12 * a.norm());
    EXPECT_NEAR(sa[0], sb[0], 1e-14);
    EXPECT_NEAR(sa[1], sb[1], 1e-14);
}

TEST(DruckerPrager, RadialPathIsIndependentOfTheNumberOfSteps) {
    const DruckerPrager m = sand();
    const Voigt6 total = 5.0 * trial_strain(-40e3, 40e3);
    auto state_one = initial_state(m);
    const Voigt6 one = testing::drive(m, Voigt6::Zero(), state_one, total, 1);
    for (int steps : {10, 1000}) {
        auto state = initial_state(m);
        const Voigt6 many = testing::drive(m, Voigt6::Zero(), state, total, steps);
        // The cone return is an affine projection along a fixed direction on a radial path, so
        // the answer is step independent up to accumulated round-off: 1e-9 relative.
        EXPECT_LT((many - one).norm(), 1e-9 * one.norm()) << steps << " steps";
        EXPECT_NEAR(state[1], state_one[1], 1e-9 * std::abs(state_one[1]));
    }
}

} // namespace
} // namespace grainload::materials
