#include "materials/voigt_algebra.hpp"
#include "materials/von_mises.hpp"
#include "tests/unit/materials/material_test_support.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace grainload::materials {
namespace {

using testing::finite_difference_tangent;
using testing::initial_state;
using testing::relative_tangent_error;

// Structural steel, SI: E = 200 GPa, nu = 0.3, sigma_0 = 250 MPa, E_T = 2 GPa.
const ElasticConstants kSteel = ElasticConstants::from_young(7850.0, 200e9, 0.3);
constexpr double kYield = 250e6;
constexpr double kTangent = 2e9;

VonMises steel(double beta) {
    return VonMises(kSteel, kYield, kTangent, beta);
}

/// sqrt(3/2) ||s - xi|| - sigma_y from the returned stress and state (independent of update()).
double yield_function(const VonMises& m, const Voigt6& stress, const std::vector<double>& state) {
    const Voigt6 back = Eigen::Map<const Voigt6>(state.data());
    return std::sqrt(1.5) * voigt::norm(voigt::deviator(stress) - back) -
           m.current_yield_stress(state);
}

// The closed-form compliance (the energy books' elastic strain, the plastic work) against the
// stiffness matrix inverted by Eigen, and back through Hooke's law: round-off, 1e-14 relative.
TEST(ElasticConstants, StrainFromStressIsTheStiffnessInverted) {
    Voigt6 stress;
    stress << -120e6, 35e6, -8e6, 14e6, -60e6, 3e6;
    const Voigt6 strain = kSteel.strain_from_stress(stress);
    const Voigt6 reference = kSteel.stiffness().inverse() * stress;
    EXPECT_LT((strain - reference).cwiseAbs().maxCoeff(), 1e-14 * reference.cwiseAbs().maxCoeff());
    EXPECT_LT((kSteel.stress_from_strain(strain) - stress).cwiseAbs().maxCoeff(),
              1e-14 * stress.cwiseAbs().maxCoeff());
}

TEST(VonMises, ElasticStepIsHookesLaw) {
    const VonMises m = steel(1.0);
    Voigt6 de;
    de << 2e-4, -1e-4, 0.5e-4, 1e-4, -2e-4, 0.3e-4;
    Voigt6 stress = Voigt6::Zero();
    auto state = initial_state(m);
    Matrix6 tangent;
    EXPECT_EQ(m.update(de, stress, state, &tangent), PlasticRegion::elastic);
    // Reference: sigma = lambda tr(eps) I + 2 G eps (tensor shear = gamma / 2), written out by
    // hand. Round-off only: 1e-14 relative.
    const double lambda = kSteel.lame_lambda();
    const double g = kSteel.shear_modulus;
    const double tr = de(0) + de(1) + de(2);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(stress(i), lambda * tr + 2.0 * g * de(i), 1e-14 * kYield);
        EXPECT_NEAR(stress(i + 3), g * de(i + 3), 1e-14 * kYield);
    }
    EXPECT_EQ(m.equivalent_plastic_strain(state), 0.0);
    EXPECT_TRUE(tangent.isApprox(kSteel.stiffness()));
}

TEST(VonMises, SimpleShearMatchesClosedForm) {
    // Simple shear gamma: tau_y = sigma_0 / sqrt3 and, after yield, with E_p the uniaxial plastic
    // modulus, tau = (tau_y + E_p gamma / 3) / (1 + E_p / 3G) for any beta (monotonic, radial).
    for (double beta : {0.0, 0.5, 1.0}) {
        const VonMises m = steel(beta);
        const double g = kSteel.shear_modulus;
        const double ep = m.plastic_modulus();
        const double gamma = 0.02;
        Voigt6 total = Voigt6::Zero();
        total(3) = gamma;
        auto state = initial_state(m);
        const Voigt6 stress = testing::drive(m, Voigt6::Zero(), state, total, 7);
        const double tau = (kYield / std::sqrt(3.0) + ep * gamma / 3.0) / (1.0 + ep / (3.0 * g));
        // Exact return on a radial path: only round-off remains, 1e-12 relative.
        EXPECT_NEAR(stress(3), tau, 1e-12 * tau) << "beta " << beta;
        EXPECT_NEAR(m.equivalent_plastic_strain(state), (gamma - tau / g) / std::sqrt(3.0), 1e-12);
    }
}

TEST(VonMises, ReturnLiesOnTheYieldSurface) {
    const VonMises m = steel(0.4);
    Voigt6 stress = Voigt6::Zero();
    auto state = initial_state(m);
    Voigt6 de;
    de << 3e-3, -1e-3, 0.2e-3, 2e-3, -1e-3, 1.5e-3;
    for (int i = 0; i < 5; ++i) {
        const Voigt6 step = i % 2 == 0 ? de : Voigt6(-0.7 * de.reverse());
        ASSERT_EQ(m.update(step, stress, state, nullptr), PlasticRegion::failure_surface);
        // Consistency after return, 1e-10 relative: the scalar equation is solved exactly.
        EXPECT_LE(std::abs(yield_function(m, stress, state)), 1e-10 * kYield);
    }
}

TEST(VonMises, TrialExactlyOnTheSurfaceIsContinuous) {
    const VonMises m = steel(0.5);
    // Uniaxial-strain direction scaled so that the trial lies exactly on f = 0: 2G eps_xx
    // (2/3) sqrt(3/2) ||(2/3, -1/3, -1/3)|| = sigma_0, i.e. q_trial = 2G eps_xx.
    const double on = kYield / (2.0 * kSteel.shear_modulus);
    Voigt6 stresses[3];
    PlasticRegion regions[3];
    const double factors[] = {1.0 - 1e-12, 1.0, 1.0 + 1e-12};
    for (int i = 0; i < 3; ++i) {
        Voigt6 de = Voigt6::Zero();
        de(0) = on * factors[i];
        stresses[i] = Voigt6::Zero();
        auto state = initial_state(m);
        regions[i] = m.update(de, stresses[i], state, nullptr);
    }
    EXPECT_EQ(regions[0], PlasticRegion::elastic);
    // Within 1e-12 of the surface the stresses differ by O(1e-12 sigma_0) across the switch.
    EXPECT_LT((stresses[2] - stresses[0]).norm(), 1e-10 * kYield);
    EXPECT_LT((stresses[1] - stresses[0]).norm(), 1e-10 * kYield);
}

TEST(VonMises, ConsistentTangentMatchesFiniteDifference) {
    for (double beta : {0.0, 0.3, 1.0}) {
        const VonMises m = steel(beta);
        Voigt6 stress = Voigt6::Zero();
        auto state = initial_state(m);
        Voigt6 pre;
        pre << 2e-3, -1e-3, -0.5e-3, 1e-3, 0.0, 0.5e-3;
        stress = testing::drive(m, stress, state, pre, 3); // yielded, with back stress
        Voigt6 de;
        de << 1e-3, 0.4e-3, -0.8e-3, 0.6e-3, -0.3e-3, 0.9e-3;
        Matrix6 tangent;
        auto probe = state;
        Voigt6 probe_stress = stress;
        ASSERT_EQ(m.update(de, probe_stress, probe, &tangent), PlasticRegion::failure_surface);
        // h = 1e-8 against strains of 1e-3: truncation O(h^2) and round-off ~1e-16 sigma / h
        // are both far below the 1e-5 relative requirement.
        const Matrix6 fd = finite_difference_tangent(m, stress, state, de, 1e-8);
        const double error = relative_tangent_error(tangent, fd, kSteel.stiffness());
        EXPECT_LT(error, 1e-5) << "beta " << beta;
        RecordProperty("fd_tangent_error_beta_" + testing::figure(beta), testing::figure(error));
    }
}

TEST(VonMises, RotatedStrainPathRotatesTheStress) {
    const VonMises m = steel(0.5);
    const Mat3 r = testing::some_rotation();
    Voigt6 a = Voigt6::Zero();
    Voigt6 b = Voigt6::Zero();
    auto sa = initial_state(m);
    auto sb = initial_state(m);
    Voigt6 de;
    de << 1e-3, -2e-3, 0.5e-3, 1.2e-3, -0.4e-3, 0.8e-3;
    for (int i = 0; i < 6; ++i) {
        const Voigt6 step = i < 3 ? de : Voigt6(-1.5 * de);
        m.update(step, a, sa, nullptr);
        m.update(testing::rotate_strain(r, step), b, sb, nullptr);
    }
    // Isotropy: exact in exact arithmetic; round-off of the rotations, 1e-12 relative.
    EXPECT_LT((testing::rotate_stress(r, a) - b).norm(), 1e-12 * a.norm());
    EXPECT_NEAR(sa[6], sb[6], 1e-14);
}

TEST(VonMises, RadialPathIsIndependentOfTheNumberOfSteps) {
    const VonMises m = steel(0.5);
    Voigt6 total;
    total << 1e-2, -4e-3, -2e-3, 6e-3, 2e-3, -3e-3;
    auto state_one = initial_state(m);
    const Voigt6 one = testing::drive(m, Voigt6::Zero(), state_one, total, 1);
    for (int steps : {10, 1000}) {
        auto state = initial_state(m);
        const Voigt6 many = testing::drive(m, Voigt6::Zero(), state, total, steps);
        // The direction of s - xi stays fixed on a radial path, so each return is exact and the
        // steps agree up to accumulated round-off (1000 additions), 1e-10 relative.
        EXPECT_LT((many - one).norm(), 1e-10 * one.norm()) << steps << " steps";
        EXPECT_NEAR(state[6], state_one[6], 1e-10 * state_one[6]);
    }
}

} // namespace
} // namespace grainload::materials
