#include "sph/neighbour_list.hpp"
#include "sph/wall_bodies.hpp"

#include <gtest/gtest.h>
#include <random>
#include <utility>
#include <vector>

namespace grainload::sph {
namespace {

Wall wall_with(int body_id, std::vector<int> bodies) {
    Wall wall;
    wall.body_id = body_id;
    wall.bodies = std::move(bodies);
    return wall;
}

// Bodies 0, 1, 2; walls with ids 3 (all bodies) and 4 (body 1 only): wall 4 is kept apart from
// bodies 0 and 2 both ways, nothing else is.
TEST(WallBodies, FilterKeepsAWallApartFromTheBodiesItDoesNotList) {
    EXPECT_TRUE(wall_body_filter({wall_with(3, {}), wall_with(4, {})}).empty());
    const WallBodyFilter filter = wall_body_filter({wall_with(3, {}), wall_with(4, {1})});
    ASSERT_EQ(filter.groups, 5);
    for (int a = 0; a < 5; ++a) {
        for (int b = 0; b < 5; ++b) {
            const bool apart = (a == 4 && b != 1) || (b == 4 && a != 1);
            EXPECT_EQ(filter.apart[static_cast<std::size_t>(a * 5 + b)] != 0, apart)
                << a << ", " << b;
        }
    }
}

// Random particles of two bodies (ids 0, 1) and one wall (id 2, frozen) that acts on body 0
// only. After drop_pairs the list is the full list less exactly the wall's pairs with body 1,
// every row's remaining entries in their original order (a restart rebuilds the same list).
TEST(WallBodies, DroppedPairsAreExactlyTheWallsPairsWithTheOtherBody) {
    std::mt19937 generator(11u);
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    const int n = 1200;
    std::vector<Vec3> points(n);
    std::vector<int> group(n);
    std::vector<char> frozen(n);
    for (int i = 0; i < n; ++i) {
        points[static_cast<std::size_t>(i)] =
            Vec3(coordinate(generator), coordinate(generator), coordinate(generator));
        group[static_cast<std::size_t>(i)] = i % 3;
        frozen[static_cast<std::size_t>(i)] = i % 3 == 2 ? 1 : 0;
    }
    NeighbourList full(0.08, 0.01, 3);
    full.update(points, frozen);
    NeighbourList filtered(0.08, 0.01, 3);
    filtered.update(points, frozen);
    const WallBodyFilter filter = wall_body_filter({wall_with(2, {0})});
    filtered.drop_pairs(group, filter.apart, filter.groups);
    Index dropped = 0;
    for (Index i = 0; i < n; ++i) {
        std::vector<std::int32_t> expected;
        for (const std::int32_t j : full.neighbours(i)) {
            const bool wall_and_other =
                (group[i] == 2 && group[j] == 1) || (group[i] == 1 && group[j] == 2);
            if (wall_and_other) {
                ++dropped;
            } else {
                expected.push_back(j);
            }
        }
        const auto row = filtered.neighbours(i);
        EXPECT_EQ(std::vector<std::int32_t>(row.begin(), row.end()), expected) << "row " << i;
    }
    EXPECT_GT(dropped, 0);
    EXPECT_EQ(filtered.pair_entries(), full.pair_entries() - dropped);
}

} // namespace
} // namespace grainload::sph
