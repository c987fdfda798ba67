// Two spheres in head-on impact against the analytic solutions of their contact laws.

#include "support/dem_scene.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace {

using namespace grainload;
using grainload::testing::dem_model;
using grainload::testing::glass;
using grainload::testing::step_until;

/// Two equal glass spheres of radius 5 mm, 1 mm apart, closing at 2 `speed` (m/s) along x
/// without gravity, with the contact law `contact` and the default step (t_c / 100).
std::string impact(const std::string& contact, const std::string& young = "10 MPa",
                   double speed = 1.0) {
    const std::string v = std::to_string(speed);
    return "[case]\nend_time = \"0.1 s\"\ngravity = \"0 0 0 m/s^2\"\n" + glass(young) +
           "[dem]\n[dem.contact]\n" + contact +
           "[[dem.body]]\nname = \"a\"\nmaterial = \"glass\"\nradius = \"5 mm\"\n"
           "centre = \"-0.0055 0 0 m\"\nvelocity = \"" +
           v +
           " 0 0 m/s\"\n"
           "[[dem.body]]\nname = \"b\"\nmaterial = \"glass\"\nradius = \"5 mm\"\n"
           "centre = \"0.0055 0 0 m\"\nvelocity = \"-" +
           v + " 0 0 m/s\"\n";
}

/// What one impact measured.
struct Impact {
    double duration = 0.0;   ///< time with the pair in contact [s]
    double peak_force = 0.0; ///< largest force on a grain [N]
    double restitution = 0.0;
    double mass = 0.0; ///< one grain's
};

Impact run_impact(dem::DemModel& model) {
    Impact result;
    const auto& g = model.grains();
    result.mass = g.mass[0];
    const double approach = (g.velocity[0] - g.velocity[1]).x();
    double last = 0.0;
    step_until(model, 0.0, 0.02, [&](double t) {
        const double dt = t - last;
        last = t;
        if (model.books().pair_contacts > 0) {
            result.duration += dt;
            result.peak_force = std::max(result.peak_force, g.force[0].norm());
        }
    });
    result.restitution = -(g.velocity[0] - g.velocity[1]).x() / approach;
    return result;
}

// The linear law given a restitution e: each pair rebounds with e. The discrete contact ends
// within one step (1/100 of its duration) of the continuous one; measured 0.5 % here, bound
// 1 %.
TEST(NormalImpact, LinearLawReboundsWithItsDeclaredRestitution) {
    for (const double e : {0.3, 0.5, 0.9}) {
        auto model = dem_model(impact("law = \"linear\"\nnormal_stiffness = \"1000 N/m\"\n"
                                      "restitution = " +
                                      std::to_string(e) + "\n"));
        const Impact result = run_impact(*model);
        std::cout << "restitution " << e << ": measured " << result.restitution << '\n';
        EXPECT_NEAR(result.restitution, e, 0.01 * e) << "e = " << e;
    }
}

// The linear law with gamma_n: the damped oscillator's half period pi / omega, omega^2 =
// k/m* - gamma_n^2/4, and e = exp(-gamma_n t_c / 2) (Schwager & Poeschel 2007), within the
// one-step resolution of the default step (1 %).
TEST(NormalImpact, LinearLawDurationAndRestitutionAreTheDampedOscillators) {
    const double k = 1000.0;
    const double gamma = 500.0;
    auto model = dem_model(impact("law = \"linear\"\nnormal_stiffness = \"1000 N/m\"\n"
                                  "gamma_n = \"500 1/s\"\n"));
    const Impact result = run_impact(*model);
    const double reduced = 0.5 * result.mass;
    const double omega = std::sqrt(k / reduced - 0.25 * gamma * gamma);
    const double duration = std::numbers::pi / omega;
    std::cout << "linear: duration " << result.duration << " s (" << duration << "), restitution "
              << result.restitution << " (" << std::exp(-0.5 * gamma * duration) << ")\n";
    EXPECT_NEAR(result.duration, duration, 0.01 * duration);
    EXPECT_NEAR(result.restitution, std::exp(-0.5 * gamma * duration), 0.01);
}

// Hertz's elastic impact (Johnson 1985, section 11.4): the largest overlap delta_m from
// (1/2) m* v^2 = (8/15) E* sqrt(R*) delta_m^(5/2), the peak force (4/3) E* sqrt(R*)
// delta_m^(3/2), the duration 2.943 delta_m / v, and no loss (e = 1). Bound 2 % on the
// duration and the force; measured well inside it at the default step.
TEST(NormalImpact, HertzImpactHasHertzsDurationAndPeakForce) {
    auto model = dem_model(impact("law = \"hertz_mindlin\"\n", "100 MPa"));
    const Impact result = run_impact(*model);
    const double young = 1.0 / (2.0 * (1.0 - 0.3 * 0.3) / 100e6);
    const double radius = 0.0025;
    const double reduced = 0.5 * result.mass;
    const double speed = 2.0;
    const double overlap =
        std::pow(15.0 * reduced * speed * speed / (16.0 * young * std::sqrt(radius)), 0.4);
    const double duration = 2.9432 * overlap / speed;
    const double force = 4.0 / 3.0 * young * std::sqrt(radius) * std::pow(overlap, 1.5);
    std::cout << "hertz: duration " << result.duration << " s (" << duration << "), peak "
              << result.peak_force << " N (" << force << "), restitution " << result.restitution
              << '\n';
    EXPECT_NEAR(result.duration, duration, 0.02 * duration);
    EXPECT_NEAR(result.peak_force, force, 0.02 * force);
    EXPECT_NEAR(result.restitution, 1.0, 1e-3);
    EXPECT_NEAR(model->shortest_contact_time(speed), duration, 1e-4 * duration);
}

// Hertz-Mindlin given a restitution: its dashpot alpha sqrt(m* k(delta)) rebounds with the same
// e at every impact speed, and alpha is solved so that e is the declared one. Measured at
// approach speeds of 0.2, 2 and 8 m/s for e = 0.5 and 0.8; bound 1 % (the step's resolution
// of the contact's end, as for the linear law).
TEST(NormalImpact, HertzLawReboundsWithItsDeclaredRestitutionAtEverySpeed) {
    for (const double e : {0.5, 0.8}) {
        for (const double speed : {0.1, 1.0, 4.0}) {
            auto model = dem_model(
                impact("law = \"hertz_mindlin\"\nrestitution = " + std::to_string(e) + "\n",
                       "100 MPa", speed));
            const Impact result = run_impact(*model);
            std::cout << "hertz restitution " << e << " at " << 2.0 * speed << " m/s: measured "
                      << result.restitution << '\n';
            EXPECT_NEAR(result.restitution, e, 0.01 * e) << "at " << 2.0 * speed << " m/s";
        }
    }
    // The map itself: e(alpha) falls from 1 without damping, and its root returns e.
    EXPECT_NEAR(dem::hertz_restitution(0.0), 1.0, 1e-6);
    EXPECT_NEAR(dem::hertz_restitution(dem::hertz_restitution_damping(0.3)), 0.3, 1e-9);
}

} // namespace
