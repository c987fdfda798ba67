// A wall with a prescribed motion: a floor sliding under a sphere drags it by Coulomb's
// friction until both move together; a floor rising carries it up.

#include "support/dem_scene.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace {

using namespace grainload;
using grainload::testing::dem_model;
using grainload::testing::glass;
using grainload::testing::step_until;

constexpr double kG = 9.81;

/// One glass sphere of radius 5 mm that cannot turn, resting on the floor z = 0, which moves
/// at `velocity` from 0.05 s (after the first contact has settled) to 1 s; wall friction 0.5.
std::unique_ptr<dem::DemModel> on_moving_floor(const std::string& velocity) {
    return dem_model("[case]\nend_time = \"1 s\"\ngravity = \"0 0 -9.81 m/s^2\"\n" + glass() +
                     "[dem]\n[dem.contact]\nlaw = \"linear\"\nnormal_stiffness = \"10000 N/m\"\n"
                     "gamma_n = \"400 1/s\"\ngamma_t = \"400 1/s\"\nwall_friction = 0.5\n"
                     "[[dem.body]]\nname = \"ball\"\nmaterial = \"glass\"\nradius = \"5 mm\"\n"
                     "centre = \"0 0 0.005 m\"\nrotation = false\n[[dem.wall]]\nname = \"floor\"\n"
                     "type = \"plane\"\npoint = \"0 0 0 m\"\nnormal = \"0 0 1\"\nvelocity = \"" +
                     velocity + "\"\nmove_start = \"0.05 s\"\nmove_end = \"1 s\"\n");
}

// The floor starts along x at 0.1 m/s: the sphere slides on it, accelerated at mu g = 4.905
// m/s^2, and sticks when it has caught up, after v / (mu g) = 20.4 ms; from then it rides with
// the floor. At 0.15 s it moves at the floor's 0.1 m/s (bound 1e-4 m/s: the stuck spring's
// stretch settles through its dashpot) and lies v t - v^2 / (2 mu g) = 8.981 mm from its start
// (measured 8.983 mm; bound 0.1 %: the contact's spring lets the catch-up end within a fraction
// of a millisecond).
TEST(MovingWall, AFloorSlidingUnderASphereDragsItByItsFriction) {
    auto model = on_moving_floor("0.1 0 0 m/s");
    step_until(*model, 0.0, 0.15, [](double) {});
    const auto& g = model->grains();
    const double expected = 0.1 * 0.1 - 0.1 * 0.1 / (2.0 * 0.5 * kG);
    std::cout << "at 0.15 s: x = " << g.position[0].x() << " m, v = " << g.velocity[0].x()
              << " m/s (expected x " << expected << " m)\n";
    EXPECT_NEAR(g.velocity[0].x(), 0.1, 1e-4);
    EXPECT_NEAR(g.position[0].x(), expected, 1e-3 * expected);
}

// The floor rising at 0.05 m/s carries the sphere: at 0.5 s it has risen with the floor by
// 0.05 m/s x 0.45 s = 22.5 mm and moves at 0.05 m/s; the contact carries its weight (it is
// deflected by m g / k_n = 0.13 mm whether the floor moves or not: bound 1e-3 of the rise).
TEST(MovingWall, ARisingFloorCarriesTheSphere) {
    auto model = on_moving_floor("0 0 0.05 m/s");
    const double start = model->grains().position[0].z();
    step_until(*model, 0.0, 0.5, [](double) {});
    const auto& g = model->grains();
    EXPECT_NEAR(g.position[0].z() - start, 0.0225, 1e-3 * 0.0225 + 1e-6);
    EXPECT_NEAR(g.velocity[0].z(), 0.05, 1e-4);
}

} // namespace
