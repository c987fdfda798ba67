// Clumps of spheres as rigid grains: the tests of Markauskas' axisymmetric particles, and the
// torque-free motion of a body with three different moments.

#include "support/dem_scene.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace {

using namespace grainload;
using grainload::testing::dem_model;
using grainload::testing::glass;
using grainload::testing::step_until;

/// One grain of radius 30 mm, `spheres` spheres on an axis along `axis`, at (0, 0, 0.3 m) moving
/// at 1 m/s along x above the floor z = 0; the paper's material (rho = 500 kg/m^3, E = 0.3 MPa,
/// nu = 0.3), Hertz contacts, no damping, no friction, its step 1.2e-4 s.
std::string one_grain(int spheres, const std::string& axis, const std::string& extra = "") {
    return "[case]\nend_time = \"2 s\"\n[[material]]\nname = \"m\"\nmodel = \"linear_elastic\"\n"
           "density = \"500 kg/m^3\"\nyoungs_modulus = \"0.3 MPa\"\npoisson_ratio = 0.3\n"
           "[dem]\ntime_step = \"1.2e-4 s\"\n[dem.contact]\nlaw = \"hertz_mindlin\"\n"
           "[[dem.body]]\nname = \"p\"\nmaterial = \"m\"\nradius = \"0.03 m\"\n"
           "centre = \"0 0 0.3 m\"\nvelocity = \"1 0 0 m/s\"\nspheres = " +
           std::to_string(spheres) + "\naxis = \"" + axis + "\"\n" + extra +
           "[[dem.wall]]\nname = \"floor\"\ntype = \"plane\"\npoint = \"0 0 0 m\"\n"
           "normal = \"0 0 1\"\n";
}

// The paper's first single-particle test: a clump of two touching spheres lying horizontally
// bounces on the floor as one sphere does. Both spheres meet the floor at once with the same
// overlap: twice the force on twice the mass, and their torques about the centre cancel. The
// centre's path over 2 s of bounces equals the sphere's to round-off (bound 1e-12 m), and the
// clump does not turn.
TEST(Clump, AHorizontalPairBouncesAsOneSphere) {
    auto pair = dem_model(one_grain(2, "1 0 0"));
    auto sphere = dem_model(one_grain(1, "1 0 0"));
    double lowest = 1.0;
    step_until(*pair, 0.0, 2.0,
               [&](double) { lowest = std::min(lowest, pair->grains().position[0].z()); });
    step_until(*sphere, 0.0, 2.0, [](double) {});
    EXPECT_LT(lowest, 0.03) << "the pair must have met the floor";
    EXPECT_LT((pair->grains().position[0] - sphere->grains().position[0]).norm(), 1e-12);
    EXPECT_EQ(pair->grains().angular_velocity[0].norm(), 0.0);
}

/// The largest departure of the total energy (translation, rotation, gravity, contacts) from
/// its start over 2 s, relative to the drop's potential energy m g h.
double energy_drift(const std::string& text, double& spin) {
    auto model = dem_model(text);
    const double start = model->energy().total();
    double worst = 0.0;
    spin = 0.0;
    step_until(*model, 0.0, 2.0, [&](double) {
        worst = std::max(worst, std::abs(model->energy().total() - start));
        spin = std::max(spin, model->grains().angular_velocity[0].norm());
    });
    return worst / (model->grains().mass[0] * 9.81 * 0.3);
}

// The paper's second test: the same clump turned by 45 deg tumbles after each impact, trading
// translational for rotational energy, while the total stays constant (no damping, no
// friction), drifting only with a larger step as the paper found: measured 1.2e-4 of m g h at
// its step and 5.2e-5 at half of it (a ratio of 2.3: the Hertz stiffness grows with the square
// root of the overlap, and its unbounded curvature at first touch costs the impacts an order).
// Bounds: below 1e-3 of m g h at 1.2e-4 s, and the error falling by at least 1.5 at half the
// step.
TEST(Clump, ATurnedPairKeepsItsEnergyWhileItTumbles) {
    double spin = 0.0;
    const std::string turned = one_grain(2, "1 0 1");
    const double coarse = energy_drift(turned, spin);
    EXPECT_GT(spin, 1.0) << "the impacts must set the pair turning";
    std::string fine = turned;
    fine.replace(fine.find("1.2e-4 s"), 8, "6e-5 s");
    const double finer = energy_drift(fine, spin);
    std::cout << "turned pair: energy drift " << coarse << " (1.2e-4 s), " << finer
              << " (6e-5 s) of m g h\n";
    EXPECT_LT(coarse, 1e-3);
    EXPECT_GT(coarse / finer, 1.5);
}

// A clump of three spheres spinning freely about an axis between its principal axes (no
// gravity, no contact): its angular velocity wanders (Euler's equations) while its angular
// momentum stays put and its rotational energy stays constant. The momentum is kept to
// round-off (each kick carries L itself, and a step's turn and its way back to omega round it
// by about 3e-16: measured 6.9e-12 of |L| after 20 000 steps, bound 1e-10); the energy to the
// midpoint turn's second order (measured 9e-11 over about 6 turns, bound 1e-6).
TEST(Clump, AFreeClumpKeepsItsAngularMomentumWhileItsSpinWanders) {
    auto model =
        dem_model("[case]\nend_time = \"1 s\"\ngravity = \"0 0 0 m/s^2\"\n" + glass() +
                  "[dem]\ntime_step = \"1e-4 s\"\n[dem.contact]\nlaw = \"hertz_mindlin\"\n"
                  "[[dem.body]]\nname = \"p\"\nmaterial = \"glass\"\nradius = \"5 mm\"\n"
                  "centre = \"0 0 0 m\"\nspheres = 3\nsphere_distance = 1.2\naxis = \"1 0.2 0\"\n"
                  "angular_velocity = \"3 5 20 rad/s\"\n");
    const auto& g = model->grains();
    const auto momentum = [&] { return Vec3(g.world_inertia(0) * g.angular_velocity[0]); };
    const Vec3 start = momentum();
    const double energy = model->energy().rotational;
    const Vec3 spin = g.angular_velocity[0];
    double worst = 0.0;
    step_until(*model, 0.0, 2.0, [&](double) {
        worst = std::max(worst, std::abs(model->energy().rotational - energy));
    });
    std::cout << "free clump: |dL|/|L| " << (momentum() - start).norm() / start.norm()
              << ", energy " << worst / energy << ", spin moved "
              << (g.angular_velocity[0] - spin).norm() << " rad/s\n";
    EXPECT_LT((momentum() - start).norm(), 1e-10 * start.norm());
    EXPECT_LT(worst, 1e-6 * energy);
    EXPECT_GT((g.angular_velocity[0] - spin).norm(), 1.0) << "the spin must wander";
}

} // namespace
