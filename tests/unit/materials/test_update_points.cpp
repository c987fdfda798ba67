// Material::update_points against update(), point by point: the batched call must give the same
// bits (the cap's returns iterate in lockstep across the points, cap_region.hpp; the others loop).
// Each point walks its own random strain path through every region of the return, with trials
// from 1e-6 to 10 stress scales, so that the block holds lockstep returns, returns that leave the
// lockstep for the trial start, the reduced start or the nested solve, and non-cap regions side
// by side.

#include "materials/drucker_prager.hpp"
#include "tests/unit/materials/cap_test_support.hpp"

#include <cstring>
#include <random>
#include <set>

namespace grainload::materials::testing {
namespace {

constexpr int kPoints = 150; // two full blocks of 64 and a partial one
constexpr int kBlock = 64;
constexpr int kSteps = 40;
/// The step the increments are taken over; the models here are rate-independent.
constexpr double kTimeStep = 1e-5;

bool same_bits(const Voigt6& a, const Voigt6& b) {
    return std::memcmp(a.data(), b.data(), sizeof(double) * 6) == 0;
}

/// Drives kPoints points along random paths, once through update() and once through
/// update_points() in blocks; returns the regions visited.
std::set<PlasticRegion> compare(const Material& m, double scale, const std::string& name) {
    const auto n_state = static_cast<std::size_t>(m.state_size());
    std::vector<Voigt6> single(kPoints, Voigt6::Zero());
    std::vector<Voigt6> blocked(kPoints, Voigt6::Zero());
    std::vector<double> single_state;
    for (int i = 0; i < kPoints; ++i) {
        const std::vector<double> s = initial_state(m);
        single_state.insert(single_state.end(), s.begin(), s.end());
    }
    std::vector<double> blocked_state = single_state;
    std::vector<double*> states(kPoints);
    for (int i = 0; i < kPoints; ++i) {
        states[static_cast<std::size_t>(i)] = blocked_state.data() + i * n_state;
    }
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double strain_scale = scale / (3.0 * m.elastic().bulk_modulus);
    std::set<PlasticRegion> visited;
    std::vector<Voigt6> increments(kPoints);
    std::vector<PlasticRegion> regions(kPoints);
    for (int step = 0; step < kSteps; ++step) {
        for (int i = 0; i < kPoints; ++i) {
            const double size =
                strain_scale * std::pow(10.0, -6.0 + 7.0 * (0.5 * unit(random) + 0.5));
            Voigt6& de = increments[static_cast<std::size_t>(i)];
            for (int c = 0; c < 6; ++c) {
                de(c) = size * unit(random);
            }
            const double i1 = invariants(single[static_cast<std::size_t>(i)])[0];
            de.head<3>().array() -= (i1 < scale ? 0.3 : -0.3) * size;
        }
        for (int i = 0; i < kPoints; i += kBlock) {
            const auto first = static_cast<std::size_t>(i);
            const auto count = static_cast<std::size_t>(std::min(kBlock, kPoints - i));
            m.update_points(std::span(increments).subspan(first, count), kTimeStep,
                            std::span(blocked).subspan(first, count),
                            std::span(states).subspan(first, count),
                            std::span(regions).subspan(first, count));
        }
        for (int i = 0; i < kPoints; ++i) {
            const auto u = static_cast<std::size_t>(i);
            const PlasticRegion region = m.update(
                increments[u], single[u], {single_state.data() + i * n_state, n_state}, nullptr);
            visited.insert(region);
            EXPECT_EQ(region, regions[u]) << name << " step " << step << " point " << i;
            EXPECT_TRUE(same_bits(single[u], blocked[u]))
                << name << " step " << step << " point " << i;
            EXPECT_EQ(
                std::memcmp(single_state.data() + i * n_state, states[u], sizeof(double) * n_state),
                0)
                << name << " step " << step << " point " << i;
        }
    }
    return visited;
}

TEST(UpdatePoints, CapGivesTheBitsOfUpdateInEveryRegion) {
    for (CapSet set : cap_sets()) {
        const GeneralizedCap m(set.elastic, set.p);
        const std::set<PlasticRegion> visited = compare(m, set.scale, set.name);
        EXPECT_TRUE(visited.count(PlasticRegion::cap)) << set.name;
        EXPECT_GE(visited.size(), 3u) << set.name;
    }
    // R = 0: the cap is a plane, returned through the corner solve outside the lockstep.
    cap::Parameters flat = thesis_cap();
    flat.R = 0.0;
    const GeneralizedCap m(thesis_elastic(), flat);
    EXPECT_TRUE(compare(m, 1.0 * kMPa, "flat").count(PlasticRegion::cap));
}

TEST(UpdatePoints, DefaultLoopGivesTheBitsOfUpdate) {
    const DruckerPrager m(ElasticConstants::from_young(2040.0, 5.84e6, 0.3), {0.2, 1e3, 0.1});
    EXPECT_GE(compare(m, 1e4, "drucker_prager").size(), 2u);
}

} // namespace
} // namespace grainload::materials::testing
