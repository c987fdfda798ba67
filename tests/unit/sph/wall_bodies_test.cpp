#include "particles/neighbour_list.hpp"
#include "sph/wall_bodies.hpp"
#include "support/sph_scene.hpp"

#include <cmath>
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
    particles::NeighbourList full(0.08, 0.01, 3);
    full.update(points, frozen);
    particles::NeighbourList filtered(0.08, 0.01, 3);
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

// Body "sunk" starts half inside a floor that acts on body "resting" only, and "resting" starts
// pressed onto the floor (its lowest particles 22.5 mm from the first wall layer, within the
// support 2h = 26 mm, yet far enough that the start-gap check passes it with a warning),
// apart from "sunk" by more than the support. A floor
// that met "sunk" would blow it out of the wall particles at once; one that does not leaves it
// in free fall: an unstressed elastic body moving uniformly has no internal force, so each of
// its particles' velocities is g t to round-off (1e-12 m/s after 200 steps of 20 us). The same
// with a symmetry plane at x = 0 that both the floor and "sunk" reach: the images of the floor's
// particles must not meet "sunk" either, nor the floor the images of "sunk".
const char* kTwoBodiesScene = R"(
[case]
end_time = "0.01 s"
dimension = 2
gravity = "0 -9.81 m/s^2"
[[material]]
name = "sand"
model = "linear_elastic"
density = "1600 kg/m^3"
youngs_modulus = "5 MPa"
poisson_ratio = 0.3
[sph]
[sph.contact]
stiffness = "5 MPa"
damping_ratio = 0.5
[[sph.body]]
name = "sunk"
material = "sand"
spacing = "10 mm"
[sph.body.shape]
type = "box"
min = "0 -15 mm"
max = "50 25 mm"
[[sph.body]]
name = "resting"
material = "sand"
spacing = "10 mm"
[sph.body.shape]
type = "box"
min = "100 12.5 mm"
max = "150 42.5 mm"
[[sph.wall]]
name = "floor"
type = "plane"
origin = "0 0 mm"
edge_u = "200 0 mm"
normal = "0 1"
bodies = ["resting"]
)";

TEST(WallBodies, ABodyTheFloorDoesNotActOnFallsFreelyThroughIt) {
    for (const std::string plane : {"", "[[sph.symmetry]]\naxis = \"x\"\nat = \"0 m\"\n"}) {
        const testing::SphScene scene(std::string(kTwoBodiesScene) + plane, "two.toml");
        const auto& model = scene.model;
        const double dt = 2e-5;
        const int steps = 200;
        for (int step = 0; step < steps; ++step) {
            model->advance(step * dt, dt);
        }
        const ParticleSet& p = model->particles();
        const double fall = -9.81 * steps * dt;
        double largest_error = 0.0;
        double pushed = 0.0;
        Index sunk = 0;
        for (Index i = 0; i < p.size(); ++i) {
            if (p.body_id[i] == model->body_id("sunk")) {
                largest_error = std::max(largest_error, (p.velocity[i] - Vec3(0, fall, 0)).norm());
                ++sunk;
            } else if (p.body_id[i] == model->body_id("resting")) {
                pushed = std::max(pushed, p.velocity[i].y() - fall);
            }
        }
        EXPECT_EQ(sunk, 20) << plane;
        EXPECT_LT(largest_error, 1e-12) << plane;
        // The floor still acts on the other body: it pushed "resting" up, by far more than
        // round-off (a tenth of the fall speed).
        EXPECT_GT(pushed, 0.1 * std::abs(fall)) << plane;
    }
}

} // namespace
} // namespace grainload::sph
