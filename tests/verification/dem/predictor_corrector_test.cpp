// The predictor-corrector of Lazarevic, Dvornik & Fresl (2002, Gradevinar 54, section 4) as the
// DEM's integrator ([dem] integrator = "predictor_corrector"): exact where the acceleration is
// constant, second order through contacts, the damped contact's analytic rebound, and its
// repeated corrector converging on the state whose forces it assumed.

#include "support/dem_scene.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <iomanip>
#include <numbers>

namespace {

using namespace grainload;
using grainload::testing::dem_model;
using grainload::testing::glass;
using grainload::testing::step_until;

constexpr const char* kPredictorCorrector = "integrator = \"predictor_corrector\"\n";

/// A glass bead of radius 5 mm, its centre `height` above a floor, falling from rest with the
/// contact law `contact`; `dem` adds keys to [dem].
std::string bead_on_floor(const std::string& dem, const std::string& contact, double height) {
    return "[case]\nend_time = \"1 s\"\n" + glass() + "[dem]\n" + dem + "[dem.contact]\n" +
           contact +
           "[[dem.body]]\nname = \"bead\"\nmaterial = \"glass\"\nradius = \"5 mm\"\n"
           "centre = \"0 0 " +
           std::to_string(height) +
           " m\"\n[[dem.wall]]\nname = \"floor\"\ntype = \"plane\"\npoint = \"0 0 0 m\"\n"
           "normal = \"0 0 1\"\n";
}

// Falling free, the corrector's acceleration at the step's end is the predictor's, g: every
// step is the exact parabola, so after 0.1 s (2000 steps of 0.05 ms) the bead has fallen
// g t^2 / 2 to round-off (bound 1e-12 of the fall; the sums of a thousand steps).
TEST(PredictorCorrector, AFreeFallIsTheExactParabola) {
    auto model =
        dem_model(bead_on_floor(std::string(kPredictorCorrector) + "time_step = \"5e-5 s\"\n",
                                "law = \"hertz_mindlin\"\n", 1.0));
    const double t = step_until(*model, 0.0, 0.1, [](double) {});
    const double fall = 0.5 * 9.81 * t * t;
    std::cout << std::setprecision(17) << "fall " << 1.0 - model->grains().position[0].z()
              << " m against " << fall << " m\n";
    EXPECT_NEAR(model->grains().position[0].z(), 1.0 - fall, 1e-12 * fall);
    EXPECT_NEAR(model->grains().velocity[0].z(), -9.81 * t, 1e-12 * 9.81 * t);
}

/// The largest departure of the bead's energy (kinetic, gravity's and the contact's) from its
/// start over 0.1 s (its first bounce on the floor and the rise after it) without damping on
/// the Hertz law, relative to the energy of the 10 mm fall, at `steps` steps per contact.
double bounce_energy_error(const std::string& dem, int steps) {
    auto model = dem_model(bead_on_floor(dem + "steps_per_contact = " + std::to_string(steps) +
                                             "\nimpact_velocity = \"0.5 m/s\"\n",
                                         "law = \"hertz_mindlin\"\n", 0.015));
    const double start = model->energy().total();
    double worst = 0.0;
    Index in_contact = 0;
    step_until(*model, 0.0, 0.1, [&](double) {
        worst = std::max(worst, std::abs(model->energy().total() - start));
        in_contact += model->books().wall_contacts > 0 ? 1 : 0;
    });
    EXPECT_GT(in_contact, steps / 2) << "the bead must bounce";
    return worst / (model->grains().mass[0] * 9.81 * 0.01);
}

// Through a contact the method is second order as velocity Verlet is: halving the step divides
// the energy error by about 4 (measured 4.0; bound [3, 5]: second order, the contact's start and
// end falling within a step where they fall); at t_c / 100 measured 1.5e-4 of the fall's
// energy, bound 3e-4.
TEST(PredictorCorrector, KeepsTheEnergyOfBouncesToSecondOrder) {
    const double coarse = bounce_energy_error(kPredictorCorrector, 50);
    const double fine = bounce_energy_error(kPredictorCorrector, 100);
    std::cout << "energy error: " << coarse << " (t_c/50), " << fine << " (t_c/100)\n";
    EXPECT_LT(fine, 3e-4);
    EXPECT_GT(coarse / fine, 3.0);
    EXPECT_LT(coarse / fine, 5.0);
}

/// Two glass spheres of radius 5 mm closing at 2 m/s head-on without gravity on the linear law
/// with k_n = 1000 N/m and gamma_n = 500 1/s: [dem] keys `dem`; the contact's duration and the
/// restitution measured.
struct Impact {
    double duration = 0.0;
    double restitution = 0.0;
    double reduced_mass = 0.0;
};

Impact damped_impact(const std::string& dem) {
    auto model = dem_model(
        "[case]\nend_time = \"0.1 s\"\ngravity = \"0 0 0 m/s^2\"\n" + glass() + "[dem]\n" + dem +
        "[dem.contact]\nlaw = \"linear\"\nnormal_stiffness = \"1000 N/m\"\ngamma_n = \"500 1/s\"\n"
        "[[dem.body]]\nname = \"a\"\nmaterial = \"glass\"\nradius = \"5 mm\"\n"
        "centre = \"-0.0055 0 0 m\"\nvelocity = \"1 0 0 m/s\"\n"
        "[[dem.body]]\nname = \"b\"\nmaterial = \"glass\"\nradius = \"5 mm\"\n"
        "centre = \"0.0055 0 0 m\"\nvelocity = \"-1 0 0 m/s\"\n");
    const auto& g = model->grains();
    Impact result;
    result.reduced_mass = 0.5 * g.mass[0];
    double last = 0.0;
    step_until(*model, 0.0, 0.02, [&](double t) {
        if (model->books().pair_contacts > 0) {
            result.duration += t - last;
        }
        last = t;
    });
    result.restitution = -(g.velocity[0] - g.velocity[1]).x() / 2.0;
    return result;
}

// The damped linear contact's duration pi / omega, omega^2 = k / m* - gamma_n^2 / 4, and its
// restitution exp(-gamma_n t_c / 2) (Schwager & Poeschel 2007), to the one-step resolution of
// the default step (1 %), with the explicit form (one pass) and with the repeated corrector
// (20 passes: without gravity the tolerance, a fraction of g, is never met).
TEST(PredictorCorrector, ADampedImpactHasTheOscillatorsDurationAndRestitution) {
    for (const std::string passes : {"1", "20"}) {
        const Impact result =
            damped_impact(std::string(kPredictorCorrector) + "corrector_passes = " + passes +
                          "\ncorrector_tolerance = 1e-6\n");
        const double omega = std::sqrt(1000.0 / result.reduced_mass - 0.25 * 500.0 * 500.0);
        const double duration = std::numbers::pi / omega;
        const double restitution = std::exp(-0.5 * 500.0 * duration);
        std::cout << passes << " passes: duration " << result.duration << " s (" << duration
                  << "), restitution " << result.restitution << " (" << restitution << ")\n";
        EXPECT_NEAR(result.duration, duration, 0.01 * duration) << passes << " passes";
        EXPECT_NEAR(result.restitution, restitution, 0.01 * restitution) << passes << " passes";
    }
}

} // namespace
