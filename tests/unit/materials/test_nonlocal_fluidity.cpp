// The non-local fluidity on the mu(I) law: the law's inverse, the local fluidity and screening,
// the viscoplastic return in its local limit against mu(I) in steady simple shear, the creep at
// a non-local excess against the relaxation of a Maxwell body, no creep without one, and the
// reader's key.

#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "materials/material_case_reader.hpp"
#include "materials/mu_i_material.hpp"
#include "materials/nonlocal_fluidity.hpp"
#include "materials/voigt_algebra.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <string>
#include <vector>

namespace grainload::materials {
namespace {

// Glass beads of Jop, Forterre & Pouliquen (2006): mu_s = tan 20.9 deg, mu_2 = tan 32.76 deg,
// I0 = 0.279, d = 0.53 mm; rho_s of soda-lime glass.
MuILaw glass_beads() {
    const double degree = std::numbers::pi / 180.0;
    return {std::tan(20.9 * degree), std::tan(32.76 * degree), 0.279, 0.53e-3, 2500.0};
}

MuIMaterial nonlocal_beads(double amplitude = 0.5) {
    return MuIMaterial(ElasticConstants::from_bulk_shear(1500.0, 2e6, 1e6), glass_beads(),
                       amplitude);
}

Voigt6 isotropic(double pressure) {
    return -pressure * voigt::identity();
}

TEST(NonlocalFluidity, TheInverseLawGivesBackTheInertialNumber) {
    const MuILaw law = glass_beads();
    // mu(I) from 1e-6 to 1e3 I0: the inverse loses the digits of mu - mu_s at the bottom of the
    // range (there 1e-7 of mu: round-off 1e-16 / 1e-7 = 1e-9 relative at most) and of mu_2 - mu
    // at the top (1e-3 of mu_2 - mu_s): allowed 1e-9.
    for (int k = -48; k <= 24; ++k) {
        const double inertial = law.i0 * std::pow(10.0, k / 8.0);
        EXPECT_NEAR(law.inertial_number_at(law.friction(inertial)) / inertial, 1.0, 1e-9) << k;
    }
    EXPECT_EQ(law.inertial_number_at(law.mu_s), 0.0);
    EXPECT_EQ(law.inertial_number_at(0.5 * law.mu_s), 0.0);
    EXPECT_TRUE(std::isinf(law.inertial_number_at(law.mu_2)));
    // The slope against a central difference (truncation (h^2/6) I''' ~ 1e-10 relative).
    const double mu = 0.5 * (law.mu_s + law.mu_2);
    const double h = 1e-6;
    const double difference =
        (law.inertial_number_at(mu + h) - law.inertial_number_at(mu - h)) / (2.0 * h);
    EXPECT_NEAR(law.inertial_number_slope(mu) / difference, 1.0, 1e-8);
}

TEST(NonlocalFluidity, LocalFluidityAndScreeningFollowTheirDefinitions) {
    const MuIMaterial material = nonlocal_beads(0.5);
    const NonlocalFluidity& f = *material.nonlocal_fluidity();
    const MuILaw& law = f.law;
    const double p = 400.0;
    const double mu = law.friction(0.1);
    // g_loc = gamma_dot / mu with gamma_dot = I sqrt(p / rho_s) / d (Henann & Kamrin 2013).
    const double rate = 0.1 * std::sqrt(p / law.grain_density) / law.grain_diameter;
    EXPECT_NEAR(f.local_fluidity(mu, p) / (rate / mu), 1.0, 1e-12);
    EXPECT_EQ(f.local_fluidity(law.mu_s, p), 0.0);
    EXPECT_EQ(f.local_fluidity(mu, 0.0), 0.0);
    // xi = A d / sqrt|mu - mu_s| on both sides of the static friction.
    for (const double ratio : {0.5 * law.mu_s, mu}) {
        const double xi = 0.5 * law.grain_diameter / std::sqrt(std::abs(ratio - law.mu_s));
        EXPECT_NEAR(f.screening(ratio) * xi * xi, 1.0, 1e-12);
    }
    EXPECT_EQ(f.screening(law.mu_s), 0.0);
}

/// tau = sqrt(J2) of a stress.
double shear_stress(const Voigt6& stress) {
    return voigt::norm(voigt::deviator(stress)) / std::sqrt(2.0);
}

// Without a non-local excess the fluidity's return is the local viscoplastic mu(I): a simple
// shear at a constant rate settles where the plastic rate equals the imposed one, tau / p =
// mu(I) with I = gamma_dot d / sqrt(p / rho_s) (Jop et al. 2006, eq. 2). The steady stress
// repeats itself step after step, so the only error is the return's Newton tolerance (1e-13 of
// tau): allowed 1e-10 on mu.
TEST(NonlocalFluidity, SteadySimpleShearFlowsAtMuOfI) {
    constexpr double kSteadyTolerance = 1e-10;
    const MuIMaterial material = nonlocal_beads();
    const MuILaw& law = material.law();
    const double p = 1000.0;
    const double dt = 1e-5;
    for (const double inertial : {1e-3, 1e-2, 0.1, 0.5}) {
        const double rate = inertial * std::sqrt(p / law.grain_density) / law.grain_diameter;
        Voigt6 stress = isotropic(p);
        std::vector<double> state(5, 0.0);
        Voigt6 increment = Voigt6::Zero();
        increment(3) = rate * dt; // engineering gamma_xy
        for (int step = 0; step < 20000; ++step) {
            material.update_over(increment, dt, stress, state, nullptr);
        }
        EXPECT_NEAR(-voigt::trace(stress) / 3.0, p, 1e-9 * p); // isochoric flow
        EXPECT_NEAR(shear_stress(stress) / p, law.friction(inertial), kSteadyTolerance)
            << "I = " << inertial;
        EXPECT_NEAR(state[2] / inertial, 1.0, 1e-8);
        EXPECT_NEAR(state[3] * law.friction(inertial) / rate, 1.0, 1e-8); // g = gamma_dot / mu
    }
}

// Below the static friction with a non-local excess g_nl and no strain: the plastic rate g_nl
// mu relaxes the shear stress like a Maxwell body, d tau / dt = -G g_nl tau / p, tau = tau_0
// exp(-G g_nl t / p). The implicit return gives (1 + G dt g_nl / p)^-n instead, within
// n (G dt g_nl / p)^2 / 2 = 5e-4 of it at t = p / (G g_nl) with 1000 steps: allowed 1e-3.
TEST(NonlocalFluidity, AStressBelowYieldCreepsAtItsExcessFluidity) {
    constexpr double kMaxwellTolerance = 1e-3;
    const MuIMaterial material = nonlocal_beads();
    const double p = 1000.0;
    const double excess = 2.0; // 1/s
    const double shear = material.elastic().shear_modulus;
    const double relaxation_time = p / (shear * excess);
    const int steps = 1000;
    const double dt = relaxation_time / steps;
    Voigt6 stress = isotropic(p);
    stress(3) = 0.5 * material.law().mu_s * p;
    const double tau0 = shear_stress(stress);
    std::vector<double> state(5, 0.0);
    for (int step = 0; step < steps; ++step) {
        state[4] = excess;
        const PlasticRegion region =
            material.update_over(Voigt6::Zero(), dt, stress, state, nullptr);
        ASSERT_EQ(region, PlasticRegion::failure_surface);
    }
    EXPECT_NEAR(shear_stress(stress) / tau0, std::exp(-1.0), kMaxwellTolerance);
    // Without the excess the same stress stays as it is, to the bit: no creep below yield.
    const Voigt6 held = stress;
    state[4] = 0.0;
    EXPECT_EQ(material.update_over(Voigt6::Zero(), dt, stress, state, nullptr),
              PlasticRegion::elastic);
    EXPECT_EQ(stress, held);
}

TEST(NonlocalFluidity, TheReaderTakesThePositiveAmplitudeOnly) {
    const std::string keys = "[[material]]\nmodel = \"mu_i\"\nmu_s = 0.375\nmu_2 = 0.6\n"
                             "i0 = 0.3\ngrain_size = \"0.5 mm\"\ngrain_density = \"2500 kg/m^3\"\n"
                             "density = \"1500 kg/m^3\"\nyoungs_modulus = \"10 MPa\"\n"
                             "poisson_ratio = 0.3\n";
    auto read = [&](const std::string& extra) {
        const auto document = io::CaseDocument::from_string(keys + extra, "case.toml");
        return read_material(document->root().array_of_tables("material").front());
    };
    const auto local = read("");
    EXPECT_EQ(local->nonlocal_fluidity(), nullptr);
    EXPECT_EQ(local->state_size(), 3);
    const auto nonlocal = read("nonlocal_amplitude = 0.48\n");
    ASSERT_NE(nonlocal->nonlocal_fluidity(), nullptr);
    EXPECT_EQ(nonlocal->nonlocal_fluidity()->amplitude, 0.48);
    EXPECT_EQ(nonlocal->state_size(), 5);
    EXPECT_EQ(nonlocal->frame_state().back().name, "fluidity");
    EXPECT_THROW(read("nonlocal_amplitude = 0.0\n"), io::CaseError);
    EXPECT_THROW(read("nonlocal_amplitude = -1.0\n"), io::CaseError);
}

} // namespace
} // namespace grainload::materials
