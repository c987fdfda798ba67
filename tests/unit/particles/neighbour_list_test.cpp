#include "particles/cell_list.hpp"
#include "particles/neighbour_list.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace grainload::particles {
namespace {

std::vector<Vec3> random_points(int count, int dimension, unsigned seed) {
    std::mt19937 generator(seed);
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    std::vector<Vec3> points(static_cast<std::size_t>(count));
    for (Vec3& x : points) {
        x = Vec3(coordinate(generator), coordinate(generator),
                 dimension == 3 ? coordinate(generator) : 0.0);
    }
    return points;
}

using PairSet = std::set<std::pair<Index, Index>>;

PairSet brute_force_pairs(const std::vector<Vec3>& points, double radius) {
    PairSet pairs;
    const auto n = static_cast<Index>(points.size());
    for (Index i = 0; i < n; ++i) {
        for (Index j = 0; j < n; ++j) {
            if (i != j && (points[i] - points[j]).norm() < radius) {
                pairs.emplace(i, j);
            }
        }
    }
    return pairs;
}

/// Pairs of the list that are within `radius` (the list may hold more, up to radius + skin).
PairSet listed_pairs(const NeighbourList& list, const std::vector<Vec3>& points, double radius) {
    PairSet pairs;
    for (Index i = 0; i < static_cast<Index>(points.size()); ++i) {
        for (const Index j : list.neighbours(i)) {
            if ((points[i] - points[j]).norm() < radius) {
                pairs.emplace(i, j);
            }
        }
    }
    return pairs;
}

TEST(NeighbourList, CellListMatchesBruteForce) {
    for (const int dimension : {2, 3}) {
        const auto points = random_points(1500, dimension, 7u + static_cast<unsigned>(dimension));
        const double radius = 0.06;
        NeighbourList list(radius, 0.0, dimension);
        list.update(points, {});
        const PairSet expected = brute_force_pairs(points, radius);
        EXPECT_EQ(listed_pairs(list, points, radius), expected) << dimension << "D";
        EXPECT_EQ(list.pair_entries(), static_cast<Index>(expected.size()));
    }
}

TEST(NeighbourList, VerletListIsReusedUntilHalfSkinAndStaysComplete) {
    const int dimension = 3;
    auto points = random_points(2000, dimension, 3u);
    const double radius = 0.08;
    const double skin = 0.02;
    NeighbourList list(radius, skin, dimension);
    EXPECT_TRUE(list.update(points, {}));
    std::mt19937 generator(11u);
    std::uniform_real_distribution<double> jitter(-1.0, 1.0);
    // Moves of at most 0.45 skin in total per particle: no rebuild, no pair lost.
    for (int step = 0; step < 3; ++step) {
        for (Vec3& x : points) {
            x +=
                Vec3(jitter(generator), jitter(generator), jitter(generator)) * (0.15 * skin / 2.0);
        }
        EXPECT_FALSE(list.update(points, {}));
        EXPECT_EQ(listed_pairs(list, points, radius), brute_force_pairs(points, radius));
    }
    points[0] += Vec3(0.6 * skin, 0.0, 0.0);
    EXPECT_TRUE(list.update(points, {}));
    EXPECT_EQ(list.rebuild_count(), 2);
    EXPECT_EQ(listed_pairs(list, points, radius), brute_force_pairs(points, radius));
}

TEST(NeighbourList, FrozenPairsAreLeftOut) {
    const std::vector<Vec3> points{Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0.2, 0, 0)};
    const std::vector<char> frozen{1, 1, 0};
    NeighbourList list(0.15, 0.0, 2);
    list.update(points, frozen);
    EXPECT_EQ(list.neighbours(0).size(), 0u);
    ASSERT_EQ(list.neighbours(1).size(), 1u);
    EXPECT_EQ(list.neighbours(1)[0], 2);
}

TEST(NeighbourList, FarOutlierDoesNotBlowUpTheGrid) {
    auto points = random_points(100, 3, 5u);
    points.emplace_back(1e6, 1e6, 1e6);
    NeighbourList list(0.01, 0.0, 3);
    list.update(points, {});
    EXPECT_EQ(listed_pairs(list, points, 0.01), brute_force_pairs(points, 0.01));
}

// Found by the checkpoint fuzzer (tests/fuzz/regressions/checkpoint/): positions of 1e47 m
// made the grid's cell count overflow its integer (undefined behaviour), and a NaN or an
// infinity has no cell at all. A particle gone astray like that must not break the list for
// the others, which keep exactly their brute-force neighbours, and the list must be built
// (not loop or allocate without end) so that the diagnosis can name the particle.
TEST(NeighbourList, AstrayParticlesAtHugeNonFiniteCoordinatesLeaveTheOthersIntact) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const Vec3& astray : {Vec3(3.3e47, 0.5, 0.5), Vec3(-1.7e308, 1.7e308, 0.0),
                               Vec3(nan, 0.5, 0.5), Vec3(0.5, inf, -inf)}) {
        auto points = random_points(200, 3, 11u);
        points.push_back(astray);
        NeighbourList list(0.1, 0.0, 3);
        list.update(points, {});
        PairSet finite = listed_pairs(list, points, 0.1);
        EXPECT_EQ(finite, brute_force_pairs(points, 0.1)) << astray.transpose();
    }
}

// Found by the case fuzzer (tests/fuzz/README.md): a floor of wall particles placed 2.2e26 m
// away coarsened the grid until the sand shared one cell, and the search turned quadratic.
// Here 2000 particles of sand in a unit cube and a floor of 400 wall particles 1e9 m above it
// (at 1e9 m a double still resolves 1e-7 m, so the floor's own pairs are real): the grid keeps
// cells of the search radius (stored sparsely), each sand particle tests the candidates of its
// 27 cells (about 27 * 2000 * 0.06^3 = 12 on average; the coarsened grid gave every one all
// 2000), and the lists, the floor's frozen pairs left out, are the brute-force ones.
TEST(NeighbourList, AWallFarFromTheSandKeepsTheCellsOfTheSearchRadius) {
    const double radius = 0.06;
    auto points = random_points(2000, 3, 13u);
    std::vector<char> frozen(points.size(), 0);
    for (const Vec3& x : random_points(400, 3, 17u)) {
        points.emplace_back(x[0], x[1], 1e9 + 0.05 * x[2]);
        frozen.push_back(1);
    }
    CellList cells;
    cells.build(points, radius, 3);
    EXPECT_TRUE(cells.sparse());
    EXPECT_EQ(cells.cell_size(), radius);
    Index candidates = 0;
    for (Index i = 0; i < 2000; ++i) {
        cells.for_each_candidate(points[static_cast<std::size_t>(i)], [&](Index) { ++candidates; });
    }
    // Mean 12 at the cube's interior, fewer at its faces: 40 per particle bounds it with room;
    // the coarsened grid gave 2000.
    EXPECT_LT(candidates, 40 * 2000);

    NeighbourList list(radius, 0.0, 3);
    list.update(points, frozen);
    PairSet expected;
    for (const auto& [i, j] : brute_force_pairs(points, radius)) {
        if (!(frozen[static_cast<std::size_t>(i)] && frozen[static_cast<std::size_t>(j)])) {
            expected.emplace(i, j);
        }
    }
    EXPECT_EQ(listed_pairs(list, points, radius), expected);
}

TEST(NeighbourList, SameKeyRowsAreTheHalvedRowsWithoutOtherKeys) {
    const auto points = random_points(1500, 3, 5u);
    // Three keys: two bodies split at x = 0.5 and a "wall" key of its own per particle below
    // z = 0.1, as continuum_key gives wall particles.
    std::vector<int> key(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        key[i] = points[i][2] < 0.1 ? -1 - static_cast<int>(i) : (points[i][0] < 0.5 ? 0 : 1);
    }
    NeighbourList list(0.06, 0.01, 3);
    list.update(points, {});
    const auto n = static_cast<Index>(points.size());
    for (Index i = 0; i < n; ++i) {
        EXPECT_FALSE(list.same_key_row(i)) << "before halve_pairs, row " << i;
    }
    list.halve_pairs(key);
    Index whole = 0;
    for (Index i = 0; i < n; ++i) {
        const auto row = list.neighbours(i);
        const bool expected = std::all_of(row.begin(), row.end(), [&](std::int32_t j) {
            return key[static_cast<std::size_t>(i)] == key[static_cast<std::size_t>(j)] && j > i;
        });
        EXPECT_EQ(list.same_key_row(i), expected) << "row " << i;
        whole += expected ? 1 : 0;
    }
    // Both kinds occur: rows inside a body, and rows next to the other body or the "wall".
    EXPECT_GT(whole, n / 4);
    EXPECT_LT(whole, n);
    list.update(points, {}, true);
    EXPECT_FALSE(list.same_key_row(0)) << "a rebuild drops the marks";
}

} // namespace
} // namespace grainload::particles
