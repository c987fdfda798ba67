// A sphere on an incline: it sticks, slides or rolls as Coulomb and rigid-body mechanics say.

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

/// One glass sphere of radius 5 mm resting on the plane z = 0, gravity tilted by `degrees`
/// about y (the incline's slope runs along +x). The normal dashpot and the tangential one
/// settle its first contact within 0.05 s; they do not act on a steady slide or roll.
std::unique_ptr<dem::DemModel> on_incline(double degrees, double friction, bool rotation) {
    const double theta = degrees * std::numbers::pi / 180.0;
    const std::string gravity = std::to_string(kG * std::sin(theta)) + " 0 " +
                                std::to_string(-kG * std::cos(theta)) + " m/s^2";
    return dem_model("[case]\nend_time = \"1 s\"\ngravity = \"" + gravity + "\"\n" + glass() +
                     "[dem]\n[dem.contact]\nlaw = \"linear\"\nnormal_stiffness = \"10000 N/m\"\n"
                     "gamma_n = \"400 1/s\"\ngamma_t = \"400 1/s\"\nwall_friction = " +
                     std::to_string(friction) +
                     "\n[[dem.body]]\nname = \"ball\"\nmaterial = \"glass\"\nradius = \"5 mm\"\n"
                     "centre = \"0 0 0.005 m\"\nrotation = " +
                     (rotation ? "true" : "false") +
                     "\n[[dem.wall]]\nname = \"slope\"\ntype = \"plane\"\npoint = \"0 0 0 m\"\n"
                     "normal = \"0 0 1\"\n");
}

/// The sphere's acceleration down the slope between 0.1 s and 0.3 s, after its first contact
/// has settled.
double slope_acceleration(dem::DemModel& model) {
    double t = step_until(model, 0.0, 0.1, [](double) {});
    const double v1 = model.grains().velocity[0].x();
    t = step_until(model, t, 0.3, [](double) {});
    const double a = (model.grains().velocity[0].x() - v1) / 0.2;
    std::cout << "acceleration down the slope " << a << " m/s^2\n";
    return a;
}

// Below the friction angle (tan 20 deg = 0.36 < 0.5) a sphere that cannot turn sticks: once its
// first contact has settled (by 0.1 s; it may slip by microns while the dashpot unloads the
// contact) the tangential spring holds it, deflected by m g sin(theta) / k_t = 1.5 micrometres.
// From 0.1 s to 0.3 s it moves less than 1e-3 of its radius, where sliding would take it
// g (sin theta - mu cos theta) t^2 / 2 further and a frictionless slope 67 mm.
TEST(Incline, ASphereThatCannotTurnSticksBelowTheFrictionAngle) {
    auto model = on_incline(20.0, 0.5, false);
    const double t = step_until(*model, 0.0, 0.1, [](double) {});
    const double settled = model->grains().position[0].x();
    step_until(*model, t, 0.3, [](double) {});
    EXPECT_LT(std::abs(model->grains().position[0].x() - settled), 1e-3 * 0.005);
    EXPECT_LT(model->grains().velocity[0].norm(), 1e-6);
}

// Above it (tan 30 deg = 0.58 > 0.3) it slides with g (sin theta - mu cos theta) = 2.356 m/s^2.
// Bound 0.5 %: the steady slide has no error of the step beyond round-off.
TEST(Incline, ASphereThatCannotTurnSlidesAboveTheFrictionAngle) {
    auto model = on_incline(30.0, 0.3, false);
    const double theta = std::numbers::pi / 6.0;
    const double expected = kG * (std::sin(theta) - 0.3 * std::cos(theta));
    EXPECT_NEAR(slope_acceleration(*model), expected, 0.005 * expected);
}

// A sphere free to turn, with mu >= (2/7) tan theta, rolls without slip at (5/7) g sin theta
// (a solid sphere, I = 2/5 m r^2), and its spin matches its speed: omega r = v.
TEST(Incline, ASphereFreeToTurnRollsWithoutSlip) {
    auto model = on_incline(20.0, 0.5, true);
    const double expected = 5.0 / 7.0 * kG * std::sin(20.0 * std::numbers::pi / 180.0);
    EXPECT_NEAR(slope_acceleration(*model), expected, 0.005 * expected);
    const auto& g = model->grains();
    EXPECT_NEAR(g.angular_velocity[0].y() * 0.005, g.velocity[0].x(), 0.005 * g.velocity[0].x());
}

// Steeper than rolling allows (mu = 0.1 < (2/7) tan 45 deg = 0.29) it slides while it turns:
// the contact slips, and the centre accelerates at g (sin theta - mu cos theta) = 6.243 m/s^2.
TEST(Incline, ASphereOnASteepSlopeSlidesWhileItTurns) {
    auto model = on_incline(45.0, 0.1, true);
    const double theta = std::numbers::pi / 4.0;
    const double expected = kG * (std::sin(theta) - 0.1 * std::cos(theta));
    EXPECT_NEAR(slope_acceleration(*model), expected, 0.005 * expected);
}

} // namespace
