// The mu(I) material: its law's limits and monotonicity, the shear rate and inertial number it
// reads, its reader and key table, and the claim that at rest it is the Drucker-Prager material
// of the cone sqrt(J2) = mu_s p bit for bit (same stresses, states, regions and tangents along
// random paths through the elastic, cone and apex regions), with no creep of a stress state at
// rest inside or on the cone.

#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "materials/cone_fit.hpp"
#include "materials/drucker_prager.hpp"
#include "materials/material_case_reader.hpp"
#include "materials/material_library.hpp"
#include "materials/mu_i_material.hpp"
#include "materials/voigt_algebra.hpp"

#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <string>

namespace grainload::materials {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Glass beads of Jop, Forterre & Pouliquen (2006): mu_s = tan 20.9 deg, mu_2 = tan 32.76 deg,
// I0 = 0.279, d = 0.53 mm; rho_s of soda-lime glass.
MuILaw glass_beads() {
    const double degree = std::numbers::pi / 180.0;
    return {std::tan(20.9 * degree), std::tan(32.76 * degree), 0.279, 0.53e-3, 2500.0};
}

std::unique_ptr<Material> build(const std::string& body) {
    const auto document = io::CaseDocument::from_string("[[material]]\n" + body, "case.toml");
    auto material = read_material(document->root().array_of_tables("material").front());
    document->reject_unknown_keys();
    return material;
}

constexpr const char* kElastic =
    "density = \"1500 kg/m^3\"\nyoungs_modulus = \"10 MPa\"\npoisson_ratio = 0.3\n";
// mu_s = 0.375 and dp_theta = 0.125 = mu_s / 3 are both exact in binary: the two readers give
// the same cone constants to the bit.
constexpr const char* kMuIKeysText = "model = \"mu_i\"\nmu_s = 0.375\nmu_2 = 0.6\ni0 = 0.3\n"
                                     "grain_size = \"0.5 mm\"\ngrain_density = \"2500 kg/m^3\"\n";
constexpr const char* kDruckerPragerKeysText =
    "model = \"drucker_prager\"\ndp_k = \"0 Pa\"\ndp_theta = 0.125\ndp_theta_flow = 0.0\n";

bool same_bits(const double* a, const double* b, std::size_t n) {
    return std::memcmp(a, b, sizeof(double) * n) == 0;
}

TEST(MuILaw, LimitsAreTheStaticAndTheLimitFriction) {
    const MuILaw law = glass_beads();
    // At rest the law must give mu_s itself, not a rounding of it: the material is then the
    // Drucker-Prager cone of mu_s to the bit.
    EXPECT_EQ(law.friction(0.0), law.mu_s);
    EXPECT_EQ(law.friction(kInfinity), law.mu_2);
    // Jop et al. (2006) eq. 2 at I = I0: half-way.
    EXPECT_NEAR(law.friction(law.i0), 0.5 * (law.mu_s + law.mu_2), 1e-15);
    // Slopes of the limits, from the same equation: mu - mu_s ~ (mu_2 - mu_s) I / I0 as I -> 0,
    // mu_2 - mu ~ (mu_2 - mu_s) I0 / I as I -> infinity; to 1e-6 relative (the next terms are
    // I/I0 = 1e-8 and I0/I = 1e-8 of them, far below).
    const double rise = law.mu_2 - law.mu_s;
    const double small = 1e-8 * law.i0;
    EXPECT_NEAR((law.friction(small) - law.mu_s) / (rise * small / law.i0), 1.0, 1e-6);
    const double large = 1e8 * law.i0;
    EXPECT_NEAR((law.mu_2 - law.friction(large)) / (rise * law.i0 / large), 1.0, 1e-6);
}

TEST(MuILaw, FrictionGrowsWithTheInertialNumber) {
    const MuILaw law = glass_beads();
    double previous = law.friction(0.0);
    // Strictly increasing from 1e-10 to 1e6 on a 1/8-decade grid (the increments there are far
    // above round-off), and never above mu_2.
    for (int k = -80; k <= 48; ++k) {
        const double mu = law.friction(std::pow(10.0, k / 8.0));
        EXPECT_GT(mu, previous) << "I = 1e" << k / 8.0;
        EXPECT_LT(mu, law.mu_2);
        previous = mu;
    }
}

TEST(MuILaw, InertialNumberAndShearRateAreJopsDefinitions) {
    const MuILaw law = glass_beads();
    // I = gamma_dot d / sqrt(p / rho_s): 100/s, 1 kPa.
    EXPECT_NEAR(law.inertial_number(100.0, 1e3), 100.0 * 0.53e-3 / std::sqrt(1e3 / 2500.0), 1e-15);
    EXPECT_EQ(law.inertial_number(0.0, 1e3), 0.0);
    EXPECT_EQ(law.inertial_number(0.0, 0.0), 0.0);
    EXPECT_EQ(law.inertial_number(1.0, 0.0), kInfinity);
    EXPECT_EQ(law.inertial_number(1.0, -5.0), kInfinity);
    // Simple shear gamma_xy = 2e-6 in 1e-5 s is du/dy = 0.2 /s; Jop's |gamma_dot| of it is the
    // same 0.2 /s. A volume change alone is no shear; uniaxial strain eps has
    // sqrt(2 D':D') = sqrt(4/3) eps per unit time. Round-off only: 1e-14 of the rates (the
    // pure volume change's 10 /s for its deviator of a few ulps).
    Voigt6 shear = Voigt6::Zero();
    shear(3) = 2e-6;
    EXPECT_NEAR(shear_rate(shear, 1e-5), 0.2, 0.2e-14);
    const Voigt6 volumetric = -1e-4 * voigt::identity();
    EXPECT_NEAR(shear_rate(volumetric, 1e-5), 0.0, 10.0e-14);
    Voigt6 uniaxial = Voigt6::Zero();
    uniaxial(0) = -3e-6;
    EXPECT_NEAR(shear_rate(uniaxial, 1e-5), std::sqrt(4.0 / 3.0) * 0.3, 0.3e-14);
    EXPECT_EQ(shear_rate(shear, kInfinity), 0.0);
}

TEST(MuIMaterial, ConeIsThePlaneStrainFitWithSinPhiEqualToMu) {
    // The stated map from mu to the cone: alpha = mu / 3 is the plane_strain fit of a
    // cohesionless, non-dilatant Mohr-Coulomb material with sin(phi) = mu, and the compression
    // fit of sin(phi_c) = 3 mu / (2 sqrt3 + mu) (docs/theory/mu_i.md). Round-off: 1e-15.
    for (const double mu : {0.2, 0.3819, 0.6434, 1.0}) {
        const DruckerPragerCone cone = MuIMaterial::cone(mu);
        const ConeConstants plane = fit_cone(ConeFit::plane_strain, std::asin(mu), 0.0, 0.0);
        EXPECT_NEAR(plane.alpha, cone.alpha, 1e-15) << mu;
        EXPECT_EQ(plane.k, cone.k);
        EXPECT_EQ(plane.alpha_flow, cone.alpha_flow);
        const double phi_c = std::asin(3.0 * mu / (2.0 * std::sqrt(3.0) + mu));
        EXPECT_NEAR(fit_cone(ConeFit::compression, phi_c, 0.0, 0.0).alpha, cone.alpha, 1e-15);
    }
}

/// Random strain increments with a volumetric drift that changes sign with the trial pressure,
/// so that paths cross the elastic region, the cone and the apex.
std::vector<Voigt6> random_path(int steps, double strain_scale, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<Voigt6> path(static_cast<std::size_t>(steps));
    for (int s = 0; s < steps; ++s) {
        Voigt6& de = path[static_cast<std::size_t>(s)];
        const double size = strain_scale * std::pow(10.0, -3.0 + 3.0 * (0.5 * unit(random) + 0.5));
        for (int c = 0; c < 6; ++c) {
            de(c) = size * unit(random);
        }
        de.head<3>().array() += (s / 25 % 2 == 0 ? -0.5 : 0.7) * size;
    }
    return path;
}

TEST(MuIMaterial, AtRestItIsTheDruckerPragerConeOfMuSBitForBit) {
    const auto mu_i = build(std::string(kMuIKeysText) + kElastic);
    const auto dp = build(std::string(kDruckerPragerKeysText) + kElastic);
    std::set<PlasticRegion> visited;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        // Strains of up to ~1e3 yield strains (1 kPa on E = 10 MPa).
        const std::vector<Voigt6> path = random_path(150, 1e-4, seed);
        Voigt6 s_mu = Voigt6::Zero();
        Voigt6 s_dp = Voigt6::Zero();
        Voigt6 s_limit = Voigt6::Zero();
        std::vector<double> st_mu(3, 0.0);
        std::vector<double> st_dp(2, 0.0);
        std::vector<double> st_limit(3, 0.0);
        for (std::size_t k = 0; k < path.size(); ++k) {
            Matrix6 d_mu;
            Matrix6 d_dp;
            // update(): the quasi-static limit; update_over() with an infinite step: zero rate.
            const PlasticRegion r_mu = mu_i->update(path[k], s_mu, st_mu, &d_mu);
            const PlasticRegion r_dp = dp->update(path[k], s_dp, st_dp, &d_dp);
            const PlasticRegion r_limit =
                mu_i->update_over(path[k], kInfinity, s_limit, st_limit, nullptr);
            visited.insert(r_dp);
            ASSERT_EQ(r_mu, r_dp) << "seed " << seed << " step " << k;
            ASSERT_EQ(r_limit, r_dp) << "seed " << seed << " step " << k;
            ASSERT_TRUE(same_bits(s_mu.data(), s_dp.data(), 6)) << "seed " << seed << " step " << k;
            ASSERT_TRUE(same_bits(s_limit.data(), s_dp.data(), 6)) << seed << " step " << k;
            ASSERT_TRUE(same_bits(st_mu.data(), st_dp.data(), 2)) << seed << " step " << k;
            ASSERT_TRUE(same_bits(d_mu.data(), d_dp.data(), 36)) << seed << " step " << k;
        }
    }
    EXPECT_TRUE(visited.count(PlasticRegion::elastic));
    EXPECT_TRUE(visited.count(PlasticRegion::failure_surface));
    EXPECT_TRUE(visited.count(PlasticRegion::apex));
}

TEST(MuIMaterial, VolumeChangeAloneAtAFiniteStepIsAtRest) {
    // No shear in the step: I = 0 however short the step, so the update is Drucker-Prager's;
    // the start stress lies on the cone (sqrt(J2) = mu_s p) so that compaction and dilation
    // both meet the cone or the apex. The volume changes are powers of two, whose deviator is
    // exactly zero (3 v and 3 v / 3 are exact).
    const auto mu_i = build(std::string(kMuIKeysText) + kElastic);
    const auto dp = build(std::string(kDruckerPragerKeysText) + kElastic);
    const double p = 1e3;
    Voigt6 start = -p * voigt::identity();
    start(3) = 0.375 * p;
    for (const double volumetric : {-0x1p-14, -0x1p-20, 0x1p-20, 0x1p-14}) {
        Voigt6 s_mu = start;
        Voigt6 s_dp = start;
        std::vector<double> st_mu(3, 0.0);
        std::vector<double> st_dp(2, 0.0);
        const Voigt6 de = volumetric * voigt::identity();
        EXPECT_EQ(mu_i->update_over(de, 1e-6, s_mu, st_mu, nullptr),
                  dp->update(de, s_dp, st_dp, nullptr));
        EXPECT_TRUE(same_bits(s_mu.data(), s_dp.data(), 6)) << volumetric;
    }
}

TEST(MuIMaterial, AShearedStepIsStrongerThanTheStaticCone) {
    // The other side of the equality above: with a rate the cone opens (mu(I) > mu_s), so the
    // same sheared plastic step ends at a larger sqrt(J2) than Drucker-Prager's. Without this
    // the equality test could pass with a material that never reads its rate.
    const auto mu_i = build(std::string(kMuIKeysText) + kElastic);
    const auto dp = build(std::string(kDruckerPragerKeysText) + kElastic);
    Voigt6 s_mu = -1e3 * voigt::identity();
    Voigt6 s_dp = s_mu;
    std::vector<double> st_mu(3, 0.0);
    std::vector<double> st_dp(2, 0.0);
    Voigt6 de = Voigt6::Zero();
    de(3) = 1e-3; // far beyond yield in one step
    ASSERT_EQ(mu_i->update_over(de, 1e-4, s_mu, st_mu, nullptr), PlasticRegion::failure_surface);
    ASSERT_EQ(dp->update(de, s_dp, st_dp, nullptr), PlasticRegion::failure_surface);
    // Shear rate 10 /s at 1 kPa: I = 10 * 0.5e-3 / sqrt(1e3 / 2500) = 7.9e-3.
    const double mu = 0.375 + 0.225 / (0.3 / (10.0 * 0.5e-3 / std::sqrt(0.4)) + 1.0);
    EXPECT_NEAR(s_mu(3) / 1e3, mu, 1e-12);
    EXPECT_NEAR(s_dp(3) / 1e3, 0.375, 1e-12);
    // The state keeps the step's I (the frames' inertial_number).
    EXPECT_NEAR(st_mu[2], 10.0 * 0.5e-3 / std::sqrt(0.4), 1e-15);
}

TEST(MuIMaterial, NoCreepAtRest) {
    // A heap at rest under zero increments for 10 000 steps of 1e-5 s (0.1 s). Inside the static
    // cone (K0 = 0.7, sqrt(J2)/p = 0.23 < mu_s) every bit stays. On it (a limit state
    // sqrt(J2) = mu_s p) the stress stays to 1e-12 and the plastic strain below 1e-12: a creeping
    // (viscoplastic) law would shear there at its rate over the 0.1 s, and the return itself
    // moves a stress on the cone by round-off only.
    const auto mu_i = build(std::string(kMuIKeysText) + kElastic);
    Voigt6 inside;
    inside << -700.0, -1000.0, -700.0, 50.0, 0.0, 0.0;
    Voigt6 limit = -1024.0 * voigt::identity();
    limit(3) = 384.0; // 0.375 * 1024
    for (const Voigt6& start : {inside, limit}) {
        Voigt6 stress = start;
        std::vector<double> state(3, 0.0);
        for (int step = 0; step < 10000; ++step) {
            mu_i->update_over(Voigt6::Zero(), 1e-5, stress, state, nullptr);
        }
        EXPECT_LE((stress - start).cwiseAbs().maxCoeff(), 1e-12 * 1024.0);
        EXPECT_LT(state[0], 1e-12);
        EXPECT_LT(std::abs(state[1]), 1e-12);
    }
    Voigt6 stress = inside;
    std::vector<double> state(3, 0.0);
    for (int step = 0; step < 10000; ++step) {
        mu_i->update_over(Voigt6::Zero(), 1e-5, stress, state, nullptr);
    }
    EXPECT_TRUE(same_bits(stress.data(), inside.data(), 6));
    EXPECT_EQ(state[0], 0.0);
}

TEST(MuIMaterial, UpdatePointsGivesTheBitsOfUpdateOver) {
    const auto mu_i = build(std::string(kMuIKeysText) + kElastic);
    const std::vector<Voigt6> path = random_path(64, 1e-4, 3);
    std::vector<Voigt6> single(path.size(), Voigt6::Zero());
    std::vector<Voigt6> blocked = single;
    std::vector<double> single_state(3 * path.size(), 0.0);
    std::vector<double> blocked_state = single_state;
    std::vector<double*> states(path.size());
    std::vector<PlasticRegion> regions(path.size());
    for (std::size_t k = 0; k < path.size(); ++k) {
        states[k] = blocked_state.data() + 3 * k;
    }
    for (int step = 0; step < 20; ++step) {
        mu_i->update_points(path, 2e-5, blocked, states, regions);
        for (std::size_t k = 0; k < path.size(); ++k) {
            const PlasticRegion region = mu_i->update_over(
                path[k], 2e-5, single[k], {single_state.data() + 3 * k, 3}, nullptr);
            ASSERT_EQ(region, regions[k]);
            ASSERT_TRUE(same_bits(single[k].data(), blocked[k].data(), 6));
        }
    }
    EXPECT_TRUE(same_bits(single_state.data(), blocked_state.data(), single_state.size()));
}

TEST(MuIMaterial, ReadsAnglesAndGrainKeysWithUnits) {
    const auto m = build(std::string("model = \"mu_i\"\nangle_s = \"20.9 deg\"\n"
                                     "angle_2 = \"32.76 deg\"\ni0 = 0.279\n"
                                     "grain_size = \"0.53 mm\"\n"
                                     "grain_density = \"2.5 g/cm^3\"\n") +
                         kElastic);
    const MuILaw& law = dynamic_cast<const MuIMaterial&>(*m).law();
    const MuILaw expected = glass_beads();
    EXPECT_NEAR(law.mu_s, expected.mu_s, 1e-15);
    EXPECT_NEAR(law.mu_2, expected.mu_2, 1e-15);
    EXPECT_EQ(law.i0, 0.279);
    EXPECT_NEAR(law.grain_diameter, 0.53e-3, 1e-18);
    EXPECT_NEAR(law.grain_density, 2500.0, 1e-12);
    EXPECT_EQ(m->model(), "mu_i");
}

TEST(MuIMaterial, RefusesInconsistentKeysNamingThem) {
    const auto fails_at = [](const std::string& keys, const std::string& key) {
        try {
            build(keys + kElastic);
        } catch (const io::CaseError& error) {
            return std::string(error.what()).find("material[0]." + key) != std::string::npos;
        }
        return false;
    };
    const std::string grains =
        "i0 = 0.3\ngrain_size = \"0.5 mm\"\ngrain_density = \"2500 kg/m^3\"\n";
    EXPECT_TRUE(fails_at(
        "model = \"mu_i\"\nmu_s = 0.4\nangle_s = \"20 deg\"\nmu_2 = 0.6\n" + grains, "angle_s"));
    EXPECT_TRUE(fails_at("model = \"mu_i\"\nmu_2 = 0.6\n" + grains, "mu_s"));
    EXPECT_TRUE(fails_at("model = \"mu_i\"\nmu_s = 0.6\nmu_2 = 0.4\n" + grains, "mu_2"));
    EXPECT_TRUE(fails_at("model = \"mu_i\"\nmu_s = 0.4\nmu_2 = 1.8\n" + grains, "mu_2"));
    EXPECT_TRUE(fails_at("model = \"mu_i\"\nmu_s = 0.4\nmu_2 = 0.6\ni0 = 0\n"
                         "grain_size = \"0.5 mm\"\ngrain_density = \"2500 kg/m^3\"\n",
                         "i0"));
    EXPECT_TRUE(fails_at("model = \"mu_i\"\nmu_s = 0.4\nmu_2 = 0.6\ni0 = 0.3\n"
                         "grain_size = \"0.5 MPa\"\ngrain_density = \"2500 kg/m^3\"\n",
                         "grain_size"));
    // Below the bulk density of kElastic (1500 kg/m^3): the bulk density was given instead.
    EXPECT_TRUE(fails_at("model = \"mu_i\"\nmu_s = 0.4\nmu_2 = 0.6\ni0 = 0.3\n"
                         "grain_size = \"0.5 mm\"\ngrain_density = \"1400 kg/m^3\"\n",
                         "grain_density"));
}

TEST(MuIMaterial, GrainSizeInItsSubTableIsTheLibrarysGrainSize) {
    // One d per material: the rheology's and Beverloo's k d (materials/material_library.hpp).
    const auto document = io::CaseDocument::from_string(
        std::string("[[material]]\nname = \"beads\"\nmodel = \"mu_i\"\n") + kElastic +
            "[material.mu_i]\nmu_s = 0.4\nmu_2 = 0.6\ni0 = 0.3\ngrain_size = \"2 mm\"\n"
            "grain_density = \"2500 kg/m^3\"\n",
        "case.toml");
    const MaterialLibrary library = read_material_library(document->root());
    document->reject_unknown_keys();
    ASSERT_TRUE(library.grain_size(0).has_value());
    EXPECT_DOUBLE_EQ(*library.grain_size(0), 2e-3);
    EXPECT_DOUBLE_EQ(dynamic_cast<const MuIMaterial&>(library[0]).law().grain_diameter, 2e-3);
}

} // namespace
} // namespace grainload::materials
