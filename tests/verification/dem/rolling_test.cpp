// Rolling resistance (Ai, Chen, Rotter & Ooi 2011, model C): a sphere rolling on a plane, or
// held on a slope, as the rigid-body mechanics of a sphere against a torque mu_r R N say.

#include "support/dem_scene.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace {

using namespace grainload;
using grainload::testing::dem_model;
using grainload::testing::glass;
using grainload::testing::step_until;

constexpr double kG = 9.81;
constexpr double kRadius = 0.005;
constexpr double kRollingFriction = 0.1;

/// One glass sphere of radius 5 mm on the plane z = 0 with Coulomb's mu = 0.5 (it never slips
/// here: rolling asks for (2/7) tan theta at most) and mu_r = 0.1, gravity tilted by `degrees`
/// about y (the slope runs along +x), started with `velocity` along x and the spin of rolling
/// without slip, omega_y = v / r, plus `twist` about the plane's normal.
std::unique_ptr<dem::DemModel> rolling_sphere(double degrees, double velocity, double twist = 0.0) {
    const double theta = degrees * std::numbers::pi / 180.0;
    const std::string gravity = std::to_string(kG * std::sin(theta)) + " 0 " +
                                std::to_string(-kG * std::cos(theta)) + " m/s^2";
    return dem_model(
        "[case]\nend_time = \"1 s\"\ngravity = \"" + gravity + "\"\n" + glass() +
        "[dem]\n[dem.contact]\nlaw = \"linear\"\nnormal_stiffness = \"10000 N/m\"\n"
        "gamma_n = \"400 1/s\"\ngamma_t = \"400 1/s\"\nwall_friction = 0.5\n"
        "wall_rolling_friction = " +
        std::to_string(kRollingFriction) +
        "\n[[dem.body]]\nname = \"ball\"\nmaterial = \"glass\"\nradius = \"5 mm\"\n"
        "centre = \"0 0 0.005 m\"\nvelocity = \"" +
        std::to_string(velocity) + " 0 0 m/s\"\nangular_velocity = \"0 " +
        std::to_string(velocity / kRadius) + " " + std::to_string(twist) +
        " rad/s\"\n[[dem.wall]]\nname = \"slope\"\ntype = \"plane\"\npoint = \"0 0 0 m\"\n"
        "normal = \"0 0 1\"\n");
}

// A sphere rolling at 0.1 m/s on a level plane meets the full torque mu_r r m g once its
// rolling spring is wound (1 mrad, 60 microseconds): I dw/dt = -r f - mu_r r m g with
// m dv/dt = f and v = w r give a constant deceleration (5/7) mu_r g = 0.7007 m/s^2 (I = 2/5 m
// r^2), so it stops after v0 / a = 0.143 s, v0^2 / (2 a) = 7.14 mm further. Bounds: 0.5 % on
// the deceleration (a steady roll, no error of the step beyond round-off); 1 % on the
// distance (the first contact's settling, 0.02 s with gamma_n = 400 1/s, rolls with a normal
// force that is not yet m g); at rest afterwards: the spring holds the sphere, below 1e-4 of
// its start speed, where a torque of constant size would rock it back and forth.
TEST(RollingResistance, ASphereRollingOnALevelPlaneStopsWhereTheTorqueStopsIt) {
    auto model = rolling_sphere(0.0, 0.1);
    double t = step_until(*model, 0.0, 0.03, [](double) {});
    const double v1 = model->grains().velocity[0].x();
    t = step_until(*model, t, 0.1, [](double) {});
    const double a = (v1 - model->grains().velocity[0].x()) / 0.07;
    const double expected = 5.0 / 7.0 * kRollingFriction * kG;
    std::cout << "deceleration " << a << " m/s^2 (expected " << expected << ")\n";
    EXPECT_NEAR(a, expected, 0.005 * expected);
    step_until(*model, t, 0.4, [](double) {});
    const double distance = 0.1 * 0.1 / (2.0 * expected);
    std::cout << "stopped after " << model->grains().position[0].x() << " m (expected " << distance
              << ")\n";
    EXPECT_NEAR(model->grains().position[0].x(), distance, 0.01 * distance);
    EXPECT_LT(model->grains().velocity[0].norm(), 1e-5);
}

// On a slope of 5 degrees (tan 5 deg = 0.087 < mu_r) the rolling spring holds a sphere that
// starts at rest: between 0.1 s and 0.3 s it moves less than 1e-3 of its radius, where without
// rolling resistance it would roll (5/7) g sin(theta) t^2 / 2 = 12 mm in that time.
TEST(RollingResistance, ASphereRestsOnASlopeBelowTheRollingFrictionAngle) {
    auto model = rolling_sphere(5.0, 0.0);
    const double t = step_until(*model, 0.0, 0.1, [](double) {});
    const double settled = model->grains().position[0].x();
    step_until(*model, t, 0.3, [](double) {});
    std::cout << "moved " << model->grains().position[0].x() - settled << " m, speed "
              << model->grains().velocity[0].norm() << " m/s\n";
    EXPECT_LT(std::abs(model->grains().position[0].x() - settled), 1e-3 * kRadius);
    EXPECT_LT(model->grains().velocity[0].norm(), 1e-6);
}

// On 10 degrees (tan = 0.176 > mu_r) it rolls, against the torque mu_r r m g cos(theta), at
// (5/7) g (sin theta - mu_r cos theta) = 0.5267 m/s^2. Bound 0.5 %, a steady roll.
TEST(RollingResistance, ASphereRollsDownASteeperSlopeSlowedByTheTorque) {
    auto model = rolling_sphere(10.0, 0.0);
    double t = step_until(*model, 0.0, 0.1, [](double) {});
    const double v1 = model->grains().velocity[0].x();
    step_until(*model, t, 0.3, [](double) {});
    const double a = (model->grains().velocity[0].x() - v1) / 0.2;
    const double theta = 10.0 * std::numbers::pi / 180.0;
    const double expected = 5.0 / 7.0 * kG * (std::sin(theta) - kRollingFriction * std::cos(theta));
    std::cout << "acceleration down the slope " << a << " m/s^2 (expected " << expected << ")\n";
    EXPECT_NEAR(a, expected, 0.005 * expected);
}

// Rolling resistance resists rolling, not twisting: a sphere spinning at 10 rad/s about the
// plane's normal (a pure twist: its contact point does not move, so Coulomb's slider carries
// nothing either) keeps its spin exactly.
TEST(RollingResistance, ATwistAboutTheNormalMeetsNoRollingTorque) {
    auto model = rolling_sphere(0.0, 0.0, 10.0);
    step_until(*model, 0.0, 0.2, [](double) {});
    EXPECT_EQ(model->grains().angular_velocity[0].z(), 10.0);
}

} // namespace
