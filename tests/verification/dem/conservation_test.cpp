// Many grains colliding: what no dissipation loses and what no external force changes.

#include "support/dem_scene.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace {

using namespace grainload;
using grainload::testing::dem_model;
using grainload::testing::glass;
using grainload::testing::step_until;

/// 150 glass grains of radius 4-5 mm dropped in a closed 6 cm box under gravity with the
/// Hertz law, no damping, no friction, at `steps` steps per contact.
std::string closed_box(int steps) {
    return "[case]\nend_time = \"1 s\"\n" + glass() +
           "[dem]\nsteps_per_contact = " + std::to_string(steps) +
           "\nimpact_velocity = \"2 m/s\"\n[dem.contact]\nlaw = \"hertz_mindlin\"\n"
           "[[dem.body]]\nname = \"beads\"\nmaterial = \"glass\"\nradius_min = \"4 mm\"\n"
           "radius_max = \"5 mm\"\ncount = 150\nmin = \"0 0 0 m\"\nmax = \"0.06 0.06 0.12 m\"\n"
           "[[dem.wall]]\nname = \"box\"\ntype = \"box\"\nmin = \"0 0 0 m\"\n"
           "max = \"0.06 0.06 0.12 m\"\nopen_top = false\n";
}

/// The largest departure of the total energy from its start over 0.3 s of collisions,
/// relative to the kinetic energy the fall gives (the gravity work at 0.3 s).
double energy_error(int steps, Index& collisions) {
    auto model = dem_model(closed_box(steps));
    const double start = model->energy().total();
    double worst = 0.0;
    collisions = 0;
    step_until(*model, 0.0, 0.3, [&](double) {
        worst = std::max(worst, std::abs(model->energy().total() - start));
        collisions = std::max(collisions, model->books().pair_contacts);
    });
    return worst / std::abs(model->energy().gravity);
}

// Velocity Verlet is second order: without damping or friction the energy is kept to O(dt^2),
// so halving the step divides the error by about 4. Measured: see the figures the test
// prints; bounds: below 1e-3 of the fall's energy at the default step, and a ratio in
// [2.5, 6] (second order with the scatter of which grains meet when).
TEST(Conservation, EnergyIsKeptToTheIntegratorsOrder) {
    Index contacts = 0;
    const double coarse = energy_error(100, contacts);
    EXPECT_GT(contacts, 20) << "the grains must collide with each other";
    const double fine = energy_error(200, contacts);
    std::cout << "energy error: " << coarse << " (t_c/100), " << fine << " (t_c/200)\n";
    EXPECT_LT(coarse, 1e-3);
    EXPECT_GT(coarse / fine, 2.5);
    EXPECT_LT(coarse / fine, 6.0);
}

/// Two clouds of 60 grains each closing at 2 m/s in free space, with friction and damping: no
/// force but the contacts', which come in opposite pairs. `contact` adds keys to [dem.contact].
std::string two_clouds(const std::string& contact = "") {
    return "[case]\nend_time = \"1 s\"\ngravity = \"0 0 0 m/s^2\"\n" + glass() +
           "[dem]\n[dem.contact]\nlaw = \"hertz_mindlin\"\ngamma_n = \"50 1/s\"\n"
           "gamma_t = \"20 1/s\"\nfriction = 0.5\n" +
           contact +
           "[[dem.body]]\nname = \"left\"\nmaterial = \"glass\"\nradius_min = \"4 mm\"\n"
           "radius_max = \"5 mm\"\ncount = 60\nmin = \"-0.06 0 0 m\"\nmax = \"0 0.05 0.05 m\"\n"
           "velocity = \"1 0.1 0 m/s\"\nseed = 3\n"
           "[[dem.body]]\nname = \"right\"\nmaterial = \"glass\"\nradius_min = \"4 mm\"\n"
           "radius_max = \"5 mm\"\ncount = 60\nmin = \"0.001 0.01 0.005 m\"\n"
           "max = \"0.061 0.06 0.055 m\"\nvelocity = \"-1 0 0 m/s\"\nseed = 7\n";
}

struct Momenta {
    Vec3 linear = Vec3::Zero();
    Vec3 angular = Vec3::Zero(); ///< about the origin: sum x × m v + I omega
};

Momenta momenta(const dem::GrainSet& g) {
    Momenta p;
    for (Index i = 0; i < g.size(); ++i) {
        p.linear += g.mass[i] * g.velocity[i];
        p.angular += g.position[i].cross(g.mass[i] * g.velocity[i]) +
                     g.world_inertia(i) * g.angular_velocity[i];
    }
    return p;
}

/// Steps the clouds until 0.05 s and checks that linear and angular momentum kept their start
/// to 1e-12 of the scene's scale m v (and m v L), some thousand steps of sums of ~1e-16 each.
void expect_momenta_kept(const std::string& scene) {
    auto model = dem_model(scene);
    const Momenta start = momenta(model->grains());
    double mass = 0.0;
    for (const double m : model->grains().mass) {
        mass += m;
    }
    Index contacts = 0;
    step_until(*model, 0.0, 0.05,
               [&](double) { contacts = std::max(contacts, model->books().pair_contacts); });
    EXPECT_GT(contacts, 8) << "the clouds must meet";
    std::cout << "most contacts at once " << contacts << ", momentum change "
              << (momenta(model->grains()).linear - start.linear).norm() << " kg m/s\n";
    const Momenta end = momenta(model->grains());
    const double scale = mass * 1.0;
    EXPECT_LT((end.linear - start.linear).norm(), 1e-12 * scale);
    EXPECT_LT((end.angular - start.angular).norm(), 1e-12 * scale * 0.06);
    double spin = 0.0;
    for (const Vec3& w : model->grains().angular_velocity) {
        spin = std::max(spin, w.norm());
    }
    EXPECT_GT(spin, 1.0) << "friction must have turned grains";
}

// The pair forces are exact opposites and their torques balance the moment of the pair about
// any point, so linear and angular momentum stay at their start to round-off through friction
// and damping.
TEST(Conservation, LinearAndAngularMomentumAreKeptToRoundOff) {
    expect_momenta_kept(two_clouds());
}

// Rolling resistance adds a couple to each pair, equal and opposite on its two grains: the
// momenta stay as they were, to the same round-off.
TEST(Conservation, RollingResistanceKeepsTheAngularMomentum) {
    expect_momenta_kept(two_clouds("rolling_friction = 0.2\n"));
}

} // namespace
