// Cohesion as Lazarevic, Dvornik & Fresl 2002 model it (eqs. 4 and 10): a linear spring that
// pulls a parting pair up to a share p_N of the lighter grain's weight, and nothing while the
// pair approaches, so that each parting costs N_c^2 / (2 k_n) of energy and nothing else.

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
constexpr double kStiffness = 40.0; // N/m: soft, so that the cohesive reach is 0.32 mm

double bead_mass() {
    return 2500.0 * 4.0 / 3.0 * std::numbers::pi * std::pow(0.005, 3);
}

/// A glass bead of radius 5 mm dropped from 10 mm above a floor, under the linear law without
/// damping (it rebounds whole), with `contact` added to [dem.contact].
std::unique_ptr<dem::DemModel> bouncing_bead(const std::string& contact) {
    return dem_model("[case]\nend_time = \"1 s\"\n" + glass() +
                     "[dem]\nsteps_per_contact = 10000\n[dem.contact]\nlaw = \"linear\"\n"
                     "normal_stiffness = \"" +
                     std::to_string(kStiffness) + " N/m\"\n" + contact +
                     "[[dem.body]]\nname = \"bead\"\nmaterial = \"glass\"\nradius = \"5 mm\"\n"
                     "centre = \"0 0 0.015 m\"\n[[dem.wall]]\nname = \"floor\"\ntype = "
                     "\"plane\"\npoint = \"0 0 0 m\"\nnormal = \"0 0 1\"\n");
}

/// The top of the bead's first rebound: the highest centre after it first moved up.
double rebound_height(dem::DemModel& model) {
    double top = 0.0;
    bool rising = false;
    step_until(model, 0.0, 0.2, [&](double) {
        const auto& g = model.grains();
        rising = rising || g.velocity[0].z() > 0.0;
        if (rising) {
            top = std::max(top, g.position[0].z());
        }
    });
    return top;
}

// The floor pulls the rising bead until it is N_c / k_n = p_N m g / k_n = 0.32 mm clear of it,
// then lets go; on the way down nothing pulled. The rebound loses N_c^2 / (2 k_n) =
// (p_N m g)^2 / (2 k_n) of its energy, so it tops out p_N^2 m g / (2 k_n) = 0.161 mm lower than
// the plain bounce for p_N = 1 (1.6 % of the 10 mm drop). Bound 1 % of that loss: the step
// t_c / 10000 crosses the reach in about 400 steps, and the pull's work is summed to about
// 1/400 of it (at the default t_c / 100, 4 steps, the loss came out 9 % too large). The plain
// bounce returns to 15 mm within 1 micrometre (no damping; the integrator's error).
TEST(Cohesion, APartingCostsTheCappedSpringsEnergy) {
    auto plain = bouncing_bead("");
    auto clinging = bouncing_bead("wall_cohesion_share = 1\n");
    const double plain_top = rebound_height(*plain);
    const double clinging_top = rebound_height(*clinging);
    const double loss = bead_mass() * kG / (2.0 * kStiffness);
    std::cout << "rebound to " << plain_top << " m plain, " << clinging_top
              << " m with cohesion: lower by " << plain_top - clinging_top << " m (expected "
              << loss << ")\n";
    EXPECT_NEAR(plain_top, 0.015, 1e-6);
    EXPECT_NEAR(plain_top - clinging_top, loss, 0.01 * loss);
}

/// Two equal beads closing head-on at 0.1 m/s each along x while both fall freely: gravity
/// moves them together, so their relative motion is the collision alone.
std::unique_ptr<dem::DemModel> closing_pair(const std::string& contact) {
    std::string text = "[case]\nend_time = \"1 s\"\n" + glass() +
                       "[dem]\nsteps_per_contact = 10000\n[dem.contact]\nlaw = \"linear\"\n"
                       "normal_stiffness = \"" +
                       std::to_string(kStiffness) + " N/m\"\n" + contact;
    for (const char* side : {"left", "right"}) {
        const bool left = side[0] == 'l';
        text += std::string("[[dem.body]]\nname = \"") + side +
                "\"\nmaterial = \"glass\"\nradius = \"5 mm\"\ncentre = \"" +
                (left ? "-0.006" : "0.006") + " 0 0 m\"\nvelocity = \"" + (left ? "0.1" : "-0.1") +
                " 0 0 m/s\"\n";
    }
    return dem_model(text);
}

// The pair's relative kinetic energy, (1/2) (m/2) v_rel^2 with v_rel = 0.2 m/s, loses
// N_c^2 / (2 k_n) with N_c = p_N m g: p_N = 1 leaves v_rel' = sqrt(v_rel^2 - 2 N_c^2 /
// (k_n m)) = 0.18358 m/s. Bound 0.5 % of the speed lost (the step as above). Without cohesion
// (p_N = 0) the pair parts at 0.2 m/s within 1e-4.
TEST(Cohesion, TwoGrainsPartingLoseTheCappedSpringsEnergy) {
    for (const double share : {0.0, 1.0}) {
        auto model = closing_pair("cohesion_share = " + std::to_string(share) + "\n");
        step_until(*model, 0.0, 0.1, [](double) {});
        const auto& g = model->grains();
        const double parting = g.velocity[1].x() - g.velocity[0].x();
        const double pull = share * bead_mass() * kG;
        const double expected = std::sqrt(0.04 - 2.0 * pull * pull / (kStiffness * bead_mass()));
        std::cout << "p_N " << share << ": parting at " << parting << " m/s (expected " << expected
                  << ")\n";
        EXPECT_NEAR(parting, expected, share > 0.0 ? 0.005 * (0.2 - expected) : 1e-4 * 0.2);
        EXPECT_EQ(g.velocity[0].z(), g.velocity[1].z());
    }
}

} // namespace
