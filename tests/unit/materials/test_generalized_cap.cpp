// Unit tests of GeneralizedCap: consistent tangent in every region, continuity across region
// boundaries, isotropy, the gamma = 0 (Drucker-Prager) and R -> 0 (flat cap) limits, the
// locked state and the parameter checks.

#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "materials/material_case_reader.hpp"
#include "tests/unit/materials/cap_test_support.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <map>
#include <random>
#include <set>

namespace grainload::materials::testing {
namespace {

/// A start point (stress + state) and a strain increment applied from it.
struct Probe {
    Voigt6 stress;
    std::vector<double> state;
    Voigt6 increment;
};

Voigt6 shear_xy(double gamma) {
    Voigt6 e = Voigt6::Zero();
    e(3) = gamma;
    return e;
}

/// Thesis sand compacted hydrostatically to I1 = X = 1 MPa, then unloaded to I1 = target,
/// so that the cap centre L lies at about 0.87 MPa.
Probe compacted(const GeneralizedCap& m, double unload_to) {
    const double x = 1.0 * kMPa;
    const cap::Parameters& c = m.parameters();
    const double ev = x / (3.0 * 30.62e9) + c.W * (1.0 - std::exp(-c.D * (x - c.X0)));
    Probe p{Voigt6::Zero(), initial_state(m), Voigt6::Zero()};
    p.stress = drive(m, p.stress, p.state, hydrostatic_strain(ev), 10);
    const double i1 = invariants(p.stress)[0];
    p.stress =
        drive(m, p.stress, p.state, hydrostatic_strain((unload_to - i1) / (3.0 * 30.62e9)), 1);
    return p;
}

/// Probes of every region (thesis parameters); the cap twice: an ordinary compaction step and a
/// trial far above the envelope, which ends next to the corner (bracketed fallback solve).
std::vector<std::pair<PlasticRegion, Probe>> probes(const GeneralizedCap& m) {
    std::map<PlasticRegion, Probe> out;
    Probe inside = compacted(m, 0.5 * kMPa);
    out[PlasticRegion::elastic] = {inside.stress, inside.state,
                                   shear_xy(2e-6) + hydrostatic_strain(1e-6)};
    out[PlasticRegion::failure_surface] = {inside.stress, inside.state,
                                           shear_xy(1e-5) + hydrostatic_strain(1e-6)};
    Probe on_cap = compacted(m, 1.0 * kMPa);
    on_cap.increment = hydrostatic_strain(2e-3) + shear_xy(3e-6);
    out[PlasticRegion::cap] = on_cap;
    Probe near_l = compacted(m, 0.85 * kMPa);
    near_l.increment = shear_xy(3e-5);
    near_l.increment(4) = 1e-5;
    out[PlasticRegion::corner] = near_l;
    Probe tension = compacted(m, 0.05 * kMPa);
    tension.increment = hydrostatic_strain(-2e-5) + shear_xy(1e-6);
    out[PlasticRegion::apex] = tension;
    std::vector<std::pair<PlasticRegion, Probe>> all(out.begin(), out.end());
    Probe above = compacted(m, 1.0 * kMPa);
    above.increment = hydrostatic_strain(1e-4) + shear_xy(2e-5);
    all.emplace_back(PlasticRegion::cap, above);
    return all;
}

TEST(GeneralizedCap, ConsistentTangentMatchesFiniteDifferenceInEveryRegion) {
    const GeneralizedCap m(thesis_elastic(), thesis_cap());
    const Matrix6 elastic = m.elastic().stiffness();
    int index = 0;
    for (const auto& [region, probe] : probes(m)) {
        Voigt6 stress = probe.stress;
        std::vector<double> state = probe.state;
        Matrix6 tangent;
        ASSERT_EQ(m.update(probe.increment, stress, state, &tangent), region)
            << "probe does not reach region " << static_cast<int>(region);
        const Matrix6 fd =
            finite_difference_tangent(m, probe.stress, probe.state, probe.increment, 1e-10);
        // Central differences with h = 1e-10 carry ~1e-9 relative error from the 1e-14 solver
        // tolerance and h^2 truncation, so 1e-5 is a safe bound that a wrong term (O(1)
        // relative, e.g. a missing hardening coupling) cannot meet.
        const double scale = std::max(tangent.cwiseAbs().maxCoeff(), 1e-6 * elastic.norm());
        const double error = (tangent - fd).cwiseAbs().maxCoeff() / scale;
        EXPECT_LT(error, 1e-5) << "region " << static_cast<int>(region);
        if (region != PlasticRegion::elastic) {
            EXPECT_GT((tangent - elastic).norm() / elastic.norm(), 1e-4)
                << "plastic tangent equals the elastic one in region " << static_cast<int>(region);
        }
        RecordProperty("tangent_error_probe_" + std::to_string(index++) + "_region_" +
                           std::to_string(static_cast<int>(region)),
                       figure(error));
    }
}

TEST(GeneralizedCap, TangentInTensionCutoffWithShearAndFlatCap) {
    cap::Parameters p = thesis_cap();
    p.gamma = 0.0;
    p.tension = 0.01 * kMPa; // F(-T) = k - theta T > 0: a true cutoff plane, not the apex
    p.R = 0.0;
    const GeneralizedCap m(thesis_elastic(), p);
    std::vector<Probe> cases;
    Probe start{Voigt6::Zero(), initial_state(m), Voigt6::Zero()};
    cases.push_back({start.stress, start.state, hydrostatic_strain(-1e-6) + shear_xy(1e-6)});
    cases.push_back({start.stress, start.state, hydrostatic_strain(-1e-6) + shear_xy(1e-5)});
    cases.push_back({start.stress, start.state, hydrostatic_strain(1e-4) + shear_xy(1e-6)});
    for (const Probe& c : cases) {
        Voigt6 stress = c.stress;
        std::vector<double> state = c.state;
        Matrix6 tangent;
        const PlasticRegion region = m.update(c.increment, stress, state, &tangent);
        EXPECT_NE(region, PlasticRegion::elastic);
        const Matrix6 fd = finite_difference_tangent(m, c.stress, c.state, c.increment, 1e-10);
        const double scale = std::max(tangent.cwiseAbs().maxCoeff(), 1.0);
        EXPECT_LT((tangent - fd).cwiseAbs().maxCoeff() / scale, 1e-5)
            << "region " << static_cast<int>(region);
    }
}

/// Largest relative jump of stress and cap position across region changes along
/// increment(t) = (1 - t) a + t b; records which region pairs were crossed.
double worst_jump(const GeneralizedCap& m, const Probe& start, const Voigt6& a, const Voigt6& b,
                  std::set<std::pair<int, int>>& crossed) {
    const auto at = [&](double t, Voigt6& stress, std::vector<double>& state) {
        stress = start.stress;
        state = start.state;
        return m.update((1.0 - t) * a + t * b, stress, state, nullptr);
    };
    Voigt6 s0;
    Voigt6 s1;
    std::vector<double> st0;
    std::vector<double> st1;
    double worst = 0.0;
    const int samples = 200;
    for (int i = 0; i < samples; ++i) {
        double lo = static_cast<double>(i) / samples;
        double hi = static_cast<double>(i + 1) / samples;
        const PlasticRegion r_lo = at(lo, s0, st0);
        if (at(hi, s1, st1) == r_lo) {
            continue;
        }
        for (int k = 0; k < 50; ++k) {
            const double mid = 0.5 * (lo + hi);
            (at(mid, s1, st1) == r_lo ? lo : hi) = mid;
        }
        const PlasticRegion a_region = at(lo, s0, st0);
        const PlasticRegion b_region = at(hi, s1, st1);
        crossed.insert({static_cast<int>(a_region), static_cast<int>(b_region)});
        const double scale = s0.norm() + m.parameters().k;
        worst = std::max(worst, (s1 - s0).norm() / scale);
        worst = std::max(worst, std::abs(st1[0] - st0[0]) / (std::abs(st0[0]) + m.parameters().k));
    }
    return worst;
}

TEST(GeneralizedCap, RegionBoundariesAreContinuous) {
    const GeneralizedCap m(thesis_elastic(), thesis_cap());
    std::set<std::pair<int, int>> crossed;
    double worst = 0.0;
    const Probe inside = compacted(m, 0.5 * kMPa);
    const Probe near_l = compacted(m, 0.85 * kMPa);
    // shear at fixed volume: elastic -> failure surface -> corner
    worst = std::max(worst, worst_jump(m, inside, Voigt6::Zero(), shear_xy(2e-4), crossed));
    worst = std::max(worst, worst_jump(m, near_l, Voigt6::Zero(), shear_xy(1e-4), crossed));
    // compression with shear: elastic -> cap, failure/corner -> cap across I1_tr = L
    worst = std::max(worst, worst_jump(m, inside, shear_xy(2e-5),
                                       shear_xy(2e-5) + hydrostatic_strain(4e-5), crossed));
    worst = std::max(worst, worst_jump(m, near_l, shear_xy(1e-4),
                                       shear_xy(1e-4) + hydrostatic_strain(2e-5), crossed));
    worst =
        std::max(worst, worst_jump(m, inside, Voigt6::Zero(), hydrostatic_strain(2e-3), crossed));
    // extension: elastic / failure surface -> apex
    worst = std::max(worst, worst_jump(m, inside, shear_xy(2e-5),
                                       shear_xy(2e-5) + hydrostatic_strain(-4e-5), crossed));
    worst =
        std::max(worst, worst_jump(m, inside, Voigt6::Zero(), hydrostatic_strain(-4e-5), crossed));
    // A jump is O(1) relative; across a bisected gap of ~1e-17 a continuous response moves by
    // ~1e-12 relative, so 1e-7 separates the two with a wide margin.
    EXPECT_LT(worst, 1e-7);
    const auto seen = [&](PlasticRegion x, PlasticRegion y) {
        return crossed.count({static_cast<int>(x), static_cast<int>(y)}) +
               crossed.count({static_cast<int>(y), static_cast<int>(x)});
    };
    EXPECT_TRUE(seen(PlasticRegion::elastic, PlasticRegion::failure_surface));
    EXPECT_TRUE(seen(PlasticRegion::elastic, PlasticRegion::cap));
    EXPECT_TRUE(seen(PlasticRegion::failure_surface, PlasticRegion::corner));
    EXPECT_TRUE(seen(PlasticRegion::corner, PlasticRegion::cap));
    EXPECT_TRUE(seen(PlasticRegion::elastic, PlasticRegion::apex) ||
                seen(PlasticRegion::failure_surface, PlasticRegion::apex));
    RecordProperty("worst_relative_jump", figure(worst));
}

TEST(GeneralizedCap, RotatingTheStrainPathRotatesTheStress) {
    const GeneralizedCap m(thesis_elastic(), thesis_cap());
    const Mat3 r = some_rotation();
    std::vector<Voigt6> path;
    Voigt6 e;
    e << -1e-3, -2e-3, -4e-3, 1e-4, -2e-4, 5e-5;
    path.push_back(e);
    e << 2e-5, -1e-5, 3e-6, 4e-5, 1e-5, -2e-5;
    path.push_back(e);
    e << 1e-4, 1e-4, 1e-4, 0.0, 3e-5, 0.0;
    path.push_back(e);
    e << 1e-3, 2e-3, 1e-3, -1e-4, 0.0, 1e-4;
    path.push_back(e);
    Voigt6 s = Voigt6::Zero();
    Voigt6 s_rot = Voigt6::Zero();
    std::vector<double> st = initial_state(m);
    std::vector<double> st_rot = initial_state(m);
    std::set<int> regions;
    for (const Voigt6& de : path) {
        for (int i = 0; i < 20; ++i) {
            regions.insert(static_cast<int>(m.update(de / 20.0, s, st, nullptr)));
            m.update(rotate_strain(r, de / 20.0), s_rot, st_rot, nullptr);
            // Round-off of the rotation (1e-16) amplified by the return; 1e-9 of the stress
            // level is far below any frame dependence, which would be O(1).
            ASSERT_LT((s_rot - rotate_stress(r, s)).norm(), 1e-9 * (s.norm() + 1.0));
            ASSERT_NEAR(st_rot[0], st[0], 1e-9 * (std::abs(st[0]) + 1.0));
        }
    }
    EXPECT_GE(regions.size(), 3u);
}

TEST(GeneralizedCap, GammaZeroIsDruckerPragerWithAssociatedFlow) {
    cap::Parameters p = thesis_cap();
    p.gamma = 0.0;
    p.theta = 0.1;
    p.X0 = 100.0 * kMPa; // cap far away: only the cone acts
    const GeneralizedCap m(thesis_elastic(), p);
    const double bulk = 30.62e9;
    const double shear = 8.23e9;
    Voigt6 stress = Voigt6::Constant(0.0);
    stress.head<3>().setConstant(-1.0 * kMPa);
    std::vector<double> state = initial_state(m);
    Voigt6 de;
    de << 1e-6, -3e-6, 2e-6, 4e-5, -1e-5, 2e-5;
    int plastic_steps = 0;
    double equivalent = 0.0;
    for (int i = 0; i < 10; ++i) {
        // Closed-form DP return: dlambda = f_tr / (G + 9 K theta^2), I1 = I1_tr + 9 K theta
        // dlambda, sqrt(J2) = sqrt(J2_tr) - G dlambda, deviator scaled radially.
        Voigt6 trial = stress + m.elastic().stiffness() * de;
        const auto [i1_tr, q_tr] = invariants(trial);
        const double f_tr = q_tr - p.k - p.theta * i1_tr;
        Voigt6 expected = trial;
        if (f_tr > 0.0) {
            const double dl = f_tr / (shear + 9.0 * bulk * p.theta * p.theta);
            const double i1 = i1_tr + 9.0 * bulk * p.theta * dl;
            const double ratio = (q_tr - shear * dl) / q_tr;
            Voigt6 s = trial;
            s.head<3>().array() += i1_tr / 3.0;
            expected = ratio * s;
            expected.head<3>().array() -= i1 / 3.0;
            // |de^p|^2 = dl^2 / 2 and deps_v^p = -3 theta dl, so sqrt(2/3 deps^p:deps^p) =
            // dl sqrt(1/3 + 2 theta^2).
            equivalent += dl * std::sqrt(1.0 / 3.0 + 2.0 * p.theta * p.theta);
            ++plastic_steps;
        }
        const PlasticRegion region = m.update(de, stress, state, nullptr);
        EXPECT_EQ(region, f_tr > 0.0 ? PlasticRegion::failure_surface : PlasticRegion::elastic);
        // Both sides evaluate the same closed form up to round-off; the cap-model Newton
        // solve is exact for a linear envelope, so 1e-12 of the stress level.
        EXPECT_LT((stress - expected).norm(), 1e-12 * stress.norm());
        const auto [i1, q] = invariants(stress);
        if (f_tr > 0.0) {
            EXPECT_NEAR(q, p.k + p.theta * i1, 1e-12 * stress.norm());
        }
    }
    EXPECT_GE(plastic_steps, 5);
    EXPECT_NEAR(m.equivalent_plastic_strain(state), equivalent, 1e-12 * equivalent);
}

TEST(GeneralizedCap, VanishingRatioGivesTheFlatCapWithoutNaN) {
    cap::Parameters flat = thesis_cap();
    flat.R = 0.0;
    cap::Parameters thin = thesis_cap();
    thin.R = 1e-8;
    const GeneralizedCap m_flat(thesis_elastic(), flat);
    const GeneralizedCap m_thin(thesis_elastic(), thin);
    Voigt6 s_flat = Voigt6::Zero();
    Voigt6 s_thin = Voigt6::Zero();
    std::vector<double> st_flat = initial_state(m_flat);
    std::vector<double> st_thin = initial_state(m_thin);
    std::vector<Voigt6> path = {hydrostatic_strain(0.05), shear_xy(2e-6),
                                shear_xy(2e-4) + hydrostatic_strain(1e-3),
                                hydrostatic_strain(-1e-3), shear_xy(-3e-4)};
    for (const Voigt6& de : path) {
        for (int i = 0; i < 10; ++i) {
            Matrix6 t_thin;
            m_flat.update(de / 10.0, s_flat, st_flat, nullptr);
            m_thin.update(de / 10.0, s_thin, st_thin, &t_thin);
            ASSERT_TRUE(s_thin.allFinite() && t_thin.allFinite());
            // The ellipse of half-height B and half-width R B differs from the plane by
            // R B ~ 1e-8 * 0.1 MPa in I1: relative 1e-6 of the stress level covers it.
            ASSERT_LT((s_thin - s_flat).norm(), 1e-6 * (s_flat.norm() + 1.0));
        }
    }
    // On the flat cap the flow is purely volumetric: hydrostatic compression keeps J2 = 0 and
    // puts the cap exactly at I1 = X = L.
    Voigt6 s = Voigt6::Zero();
    std::vector<double> st = initial_state(m_flat);
    s = drive(m_flat, s, st, hydrostatic_strain(0.05), 3);
    EXPECT_NEAR(st[GeneralizedCap::kCapPosition], invariants(s)[0], 1e-9 * invariants(s)[0]);
    EXPECT_EQ(st[GeneralizedCap::kCapPosition], st[GeneralizedCap::kHardeningParameter]);
}

// Near the apex of the thesis sand (k = gamma, X0 = 0: the cap starts at the origin) the
// envelope, the cap and the hardening law are linear in the stress to relative O(B1 I1) and
// O(D X), so a step's return is homogeneous of degree one in its increment: the stress and the
// hardening of a step 1e-24 times smaller are 1e-24 times the larger step's, however far below
// k's round-off they lie (a free-falling grain's stresses are of 1e-85 to 1e-9 Pa). The
// tolerance is the larger step's nonlinearity, B1 I1 ~ 1e-10, and the return's 1e-14.
TEST(GeneralizedCap, ReturnsAtTheApexScaleWithTheIncrement) {
    const GeneralizedCap m(thesis_elastic(), thesis_cap());
    Voigt6 direction = hydrostatic_strain(1.0) + shear_xy(0.3);
    direction(4) = -0.2;
    auto step = [&](double scale) {
        Voigt6 stress = Voigt6::Zero();
        std::vector<double> state = initial_state(m);
        const PlasticRegion region = m.update(scale * direction, stress, state, nullptr);
        EXPECT_EQ(region, PlasticRegion::cap) << scale;
        return std::pair{Voigt6(stress / scale), state};
    };
    constexpr double kLarge = 1e-16; // I1 ~ 1e-5 Pa: B1 I1 ~ 1e-10
    constexpr double kSmall = 1e-40; // I1 ~ 1e-29 Pa, 1e-34 of k
    const auto [large, large_state] = step(kLarge);
    const auto [small, small_state] = step(kSmall);
    const double size = large.cwiseAbs().maxCoeff();
    ASSERT_GT(size, 0.0);
    EXPECT_LT((large - small).cwiseAbs().maxCoeff(), 1e-8 * size) << large.transpose() << "\n"
                                                                  << small.transpose();
    for (const int k : {GeneralizedCap::kCapPosition, GeneralizedCap::kHardeningParameter,
                        GeneralizedCap::kPlasticVolumetricStrain}) {
        EXPECT_GT(large_state[k], 0.0) << k;
        EXPECT_NEAR(small_state[k] / kSmall, large_state[k] / kLarge,
                    1e-8 * large_state[k] / kLarge)
            << k;
    }
}

TEST(GeneralizedCap, LockedStateStaysFiniteAndElastic) {
    const GeneralizedCap m(thesis_elastic(), thesis_cap());
    Voigt6 stress = Voigt6::Zero();
    std::vector<double> state = initial_state(m);
    // eps_v = 0.2 > W = 0.18: compaction is exhausted, exp(-D X) underflows to 0.
    stress = drive(m, stress, state, hydrostatic_strain(0.2), 5);
    EXPECT_DOUBLE_EQ(state[GeneralizedCap::kPlasticVolumetricStrain], 0.18);
    const double i1 = invariants(stress)[0];
    // Further compression of the locked material is elastic: dI1 = 3 K deps_v exactly.
    stress = drive(m, stress, state, hydrostatic_strain(1e-3), 3);
    EXPECT_NEAR(invariants(stress)[0] - i1, 3.0 * 30.62e9 * 1e-3, 1e-9 * i1);
    for (const Voigt6& de :
         {shear_xy(0.05), hydrostatic_strain(-0.05), shear_xy(-0.1), hydrostatic_strain(0.5)}) {
        Matrix6 tangent;
        m.update(de, stress, state, &tangent);
        ASSERT_TRUE(stress.allFinite() && tangent.allFinite());
        for (double v : state) {
            ASSERT_TRUE(std::isfinite(v));
        }
    }
}

TEST(GeneralizedCap, RandomExtremeIncrementsStayFiniteAndAdmissible) {
    const cap::Parameters p = thesis_cap();
    const GeneralizedCap m(thesis_elastic(), p);
    Voigt6 stress = Voigt6::Zero();
    std::vector<double> state = initial_state(m);
    std::mt19937 random(12345);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::set<PlasticRegion> visited;
    for (int i = 0; i < 3000; ++i) {
        // Magnitudes from 1e-10 to 1e-3 (up to 90 MPa of trial stress), with a volumetric bias
        // that keeps I1 wandering around 1 MPa: every region is visited.
        const double size = std::pow(10.0, -10.0 + 7.0 * (0.5 * unit(random) + 0.5));
        Voigt6 de;
        for (int c = 0; c < 6; ++c) {
            de(c) = size * unit(random);
        }
        de.head<3>().array() -= (invariants(stress)[0] < kMPa ? 0.3 : -0.3) * size;
        Matrix6 tangent;
        visited.insert(m.update(de, stress, state, &tangent));
        ASSERT_TRUE(stress.allFinite() && tangent.allFinite()) << "increment " << i;
        const auto [i1, q] = invariants(stress);
        const double l = state[GeneralizedCap::kHardeningParameter];
        const double b = envelope_of(p, l);
        // Admissible to round-off of the trial stress (up to 3K * 1e-3 ~ 1e8 Pa, 1e-16 each).
        const double slack = 1e-12 * (std::abs(i1) + q) + 1e-9 * p.k;
        ASSERT_GE(i1, -slack) << "increment " << i;
        ASSERT_LE(q, envelope_of(p, i1) + slack) << "increment " << i;
        if (i1 > l) {
            ASSERT_LE(std::sqrt((i1 - l) * (i1 - l) / (p.R * p.R) + q * q), b + slack)
                << "increment " << i;
        }
    }
    EXPECT_EQ(visited.size(), 5u); // every region was exercised
}

TEST(GeneralizedCap, StateNamesAndInitialCap) {
    const GeneralizedCap m(thesis_elastic(), thesis_cap());
    const std::vector<std::string> names = m.state_names();
    ASSERT_EQ(static_cast<int>(names.size()), m.state_size());
    EXPECT_EQ(names[GeneralizedCap::kCapPosition], "cap_position");
    EXPECT_EQ(names[GeneralizedCap::kHardeningParameter], "hardening_parameter");
    EXPECT_EQ(names[GeneralizedCap::kPlasticVolumetricStrain], "plastic_volumetric_strain");
    EXPECT_EQ(names[GeneralizedCap::kEquivalentPlasticStrain], "equivalent_plastic_strain");
    const std::vector<double> state = initial_state(m);
    // Thesis set: k = gamma makes F(0) = 0, so X0 = 0 puts kappa0 = L0 = 0 at the apex.
    EXPECT_EQ(state[GeneralizedCap::kCapPosition], 0.0);
    EXPECT_NEAR(state[GeneralizedCap::kHardeningParameter], 0.0, 1e-9);
    EXPECT_EQ(state[GeneralizedCap::kPlasticVolumetricStrain], 0.0);
}

TEST(GeneralizedCap, RejectsParametersWithoutElasticRegion) {
    cap::Parameters p = thesis_cap();
    p.W = 0.0;
    EXPECT_THROW(GeneralizedCap(thesis_elastic(), p), std::invalid_argument);
    p = thesis_cap();
    p.theta = 0.0;
    p.k = 0.0;
    EXPECT_THROW(GeneralizedCap(thesis_elastic(), p), std::invalid_argument);
    p = thesis_cap();
    p.R = -1.0;
    EXPECT_EQ(GeneralizedCap::check(p).first, "cap_R");
}

std::unique_ptr<Material> from_case(const std::string& cap_keys) {
    const auto document = io::CaseDocument::from_string(
        "[[material]]\nmodel = \"generalized_cap\"\ndensity = \"2099 kg/m^3\"\n"
        "bulk_modulus = \"30.62 GPa\"\nshear_modulus = \"8.23 GPa\"\n" +
            cap_keys,
        "case.toml");
    auto material = read_material(document->root().array_of_tables("material").front());
    document->reject_unknown_keys();
    return material;
}

std::string thesis_keys(const std::string& k, const std::string& w) {
    return "cap_k = " + k + "\ncap_theta = 0.03\ncap_gamma = \"0.03858 MPa\"\n" +
           "cap_beta = \"9.0 1/MPa\"\ncap_D = \"7.25 1/MPa\"\ncap_W = " + w +
           "\ncap_X0 = \"0 MPa\"\ncap_R = 2.0\ntension_cutoff = \"0 MPa\"\n";
}

TEST(GeneralizedCap, ReadsTheThesisSetWithExplicitUnits) {
    const auto m = from_case(thesis_keys("\"0.03858 MPa\"", "0.18"));
    const auto& cap = dynamic_cast<const GeneralizedCap&>(*m);
    const cap::Parameters expected = thesis_cap();
    // Unit conversion is a product of two decimals: equal to a few ulps.
    EXPECT_DOUBLE_EQ(cap.parameters().k, expected.k);
    EXPECT_DOUBLE_EQ(cap.parameters().beta, expected.beta);
    EXPECT_DOUBLE_EQ(cap.parameters().D, expected.D);
    EXPECT_DOUBLE_EQ(cap.parameters().gamma, expected.gamma);
    EXPECT_DOUBLE_EQ(cap.parameters().R, 2.0);
    EXPECT_DOUBLE_EQ(m->elastic().bulk_modulus, 30.62e9);
}

TEST(GeneralizedCap, RefusesUnitlessStressesAndBadValues) {
    // The thesis prints k without a unit; read as Pa it would be off by 1e6: refused.
    EXPECT_THROW(from_case(thesis_keys("0.03858", "0.18")), io::CaseError);
    EXPECT_THROW(from_case(thesis_keys("\"0.03858 MPa\"", "-0.18")), io::CaseError);
}

} // namespace
} // namespace grainload::materials::testing
