// The DEM sources: grains, spheres or clumps, appear at their rate, clear of each other and of
// the walls, until their count; a full box makes them wait, and says so.

#include "dem/grain_generator.hpp"
#include "io/case_error.hpp"
#include "support/dem_scene.hpp"

#include <gtest/gtest.h>

namespace {

using namespace grainload;
using grainload::testing::dem_model;
using grainload::testing::glass;
using grainload::testing::step_until;

/// Beads of radius 4-5 mm rained at `rate` into a 0.04 m box inside a closed box wall, without
/// gravity, so that they stay where they appear (velocity 0).
/// `clump`: keys that make the beads clumps ("spheres = 3\n").
std::unique_ptr<dem::DemModel> raining(const std::string& rate, int count,
                                       const std::string& clump = "",
                                       const std::string& box = "0.04 0.04 0.04 m") {
    return dem_model("[case]\nend_time = \"1 s\"\ngravity = \"0 0 0 m/s^2\"\n" + glass() +
                     "[dem]\n[dem.contact]\nlaw = \"hertz_mindlin\"\ngamma_n = \"100 1/s\"\n"
                     "[[dem.body]]\nname = \"beads\"\nmaterial = \"glass\"\nradius_min = \"4 "
                     "mm\"\nradius_max = \"5 mm\"\n" +
                     clump +
                     "[[dem.source]]\nname = \"feed\"\nbody = \"beads\"\nmin = \"0 0 0 m\"\n"
                     "max = \"" +
                     box + "\"\nrate = \"" + rate + "\"\ncount = " + std::to_string(count) +
                     "\nstart = \"0.01 s\"\n"
                     "[[dem.wall]]\nname = \"box\"\ntype = \"box\"\nmin = \"0 0 0 m\"\n"
                     "max = \"0.04 0.04 0.04 m\"\nopen_top = false\n");
}

/// The smallest gap between two spheres, or a sphere and the box's faces (negative: overlap).
double smallest_gap(const dem::SphereSet& s) {
    double gap = 1.0;
    for (Index i = 0; i < s.size(); ++i) {
        for (Index j = i + 1; j < s.size(); ++j) {
            gap = std::min(gap, (s.position[i] - s.position[j]).norm() - s.radius[i] - s.radius[j]);
        }
        for (int a = 0; a < 3; ++a) {
            gap = std::min(
                {gap, s.position[i][a] - s.radius[i], 0.04 - s.position[i][a] - s.radius[i]});
        }
    }
    return gap;
}

// From its start at 0.01 s a source of 100 grains per second has made floor(100 (t - 0.01))
// by t (the rate's running sum, whole grains): 3 at 0.045 s, and all 5 of its count by 0.1 s,
// none after; each clear of the others and of the box's faces.
TEST(GrainSources, GrainsAppearAtTheirRateUntilTheirCount) {
    auto model = raining("100 1/s", 5);
    double t = step_until(*model, 0.0, 0.045, [](double) {});
    EXPECT_EQ(model->grains().size(), 3);
    t = step_until(*model, t, 0.2, [](double) {});
    EXPECT_EQ(model->grains().size(), 5);
    EXPECT_GE(smallest_gap(model->spheres()), 0.0);
}

// Eighty grains asked for at once in a box that holds some twenty at random (random sequential
// addition jams near 0.38 of the volume: 0.38 x 6.4e-5 m^3 / 4.2e-7 m^3 = 58 at most, far fewer
// within 100 draws each): the source makes what fits, none overlapping, keeps the rest due, and
// says once in the log that it waits for room.
TEST(GrainSources, AFullBoxMakesTheGrainsWait) {
    auto model = raining("1e6 1/s", 80);
    step_until(*model, 0.0, 0.02, [](double) {});
    const Index made = model->grains().size();
    EXPECT_GT(made, 5);
    EXPECT_LT(made, 80);
    EXPECT_GE(smallest_gap(model->spheres()), -1e-9) << "grains may only have settled into contact";
    const auto events = model->take_events();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_NE(events[0].find("source feed: its box is full"), std::string::npos) << events[0];
}

// Clumps of three touching spheres rained in at once, more than the box holds: each grain
// whole (three spheres, the mass of three spheres of its radius), turned at random (no two of
// the first grains alike), and every sphere clear of every other, of another clump's and of
// the box's faces. A box shorter than the longest clump turned any way, 2 x 5 mm x 3 = 30 mm,
// is refused.
TEST(GrainSources, ClumpsAppearWholeTurnedAtRandomAndClear) {
    auto model = raining("1e6 1/s", 40, "spheres = 3\n");
    step_until(*model, 0.0, 0.02, [](double) {});
    const dem::GrainSet& grains = model->grains();
    ASSERT_GT(grains.size(), 3);
    EXPECT_LT(grains.size(), 40);
    EXPECT_EQ(model->spheres().size(), 3 * grains.size());
    EXPECT_GE(smallest_gap(model->spheres()), -1e-9) << "grains may only have settled into contact";
    for (Index g = 0; g < grains.size(); ++g) {
        const double r = model->spheres().radius[static_cast<std::size_t>(3 * g)];
        EXPECT_NEAR(grains.mass[g], 3.0 * dem::sphere_mass(r, 2500.0), 1e-15);
    }
    EXPECT_GT(grains.orientation[0].angularDistance(grains.orientation[1]), 1e-6);
    EXPECT_GT(grains.orientation[1].angularDistance(grains.orientation[2]), 1e-6);
    EXPECT_THROW(raining("100 1/s", 5, "spheres = 3\n", "0.04 0.04 0.029 m"), io::CaseError);
    EXPECT_NO_THROW(raining("100 1/s", 5, "spheres = 3\n", "0.04 0.04 0.03 m"));
}

// Dumbbells of a sphere of the drawn radius r and one of r/2 rained in at once: each grain
// whole (its second sphere half the first's radius, its mass (1 + 1/8) spheres of radius r) and
// every sphere clear of every other by its own radius.
TEST(GrainSources, ClumpsOfUnequalSpheresAppearWholeAndClear) {
    auto model =
        raining("1e6 1/s", 40, "sphere_centres = [0, 0, 0, 1.5, 0, 0]\nsphere_radii = [1, 0.5]\n");
    step_until(*model, 0.0, 0.02, [](double) {});
    const dem::GrainSet& grains = model->grains();
    const dem::SphereSet& spheres = model->spheres();
    ASSERT_GT(grains.size(), 3);
    EXPECT_EQ(spheres.size(), 2 * grains.size());
    EXPECT_GE(smallest_gap(spheres), -1e-9) << "grains may only have settled into contact";
    for (Index g = 0; g < grains.size(); ++g) {
        const double r = spheres.radius[static_cast<std::size_t>(2 * g)];
        EXPECT_EQ(spheres.radius[static_cast<std::size_t>(2 * g + 1)], 0.5 * r);
        EXPECT_NEAR(grains.mass[g], 1.125 * dem::sphere_mass(r, 2500.0), 1e-15);
    }
}

// What `grainload check` counts: the grains the source makes by the end time (its count, or its
// rate over its window when that is fewer), each from the mean arrival time of its source's
// grains: 5 grains from 0.01 s at 100 per second arrive on average at 0.035 s, so over 1000
// steps to 1 s they make 5 x 1000 x 0.965 sphere-steps; to 0.035 s only 2 are made, on average
// at 0.02 s. A clump of three spheres counts three times a sphere.
TEST(GrainSources, TheEstimateCountsTheSpheresTheyWillMake) {
    auto model = raining("100 1/s", 5);
    EXPECT_EQ(model->most_grains(1.0), 5);
    EXPECT_DOUBLE_EQ(model->sphere_steps(1000.0, 1.0), 5 * 1000 * 0.965);
    EXPECT_EQ(model->most_grains(0.035), 2);
    EXPECT_DOUBLE_EQ(model->sphere_steps(1000.0, 0.035), 2 * 1000 * (0.015 / 0.035));
    auto clumps = raining("100 1/s", 5, "spheres = 3\n", "0.04 0.04 0.03 m");
    EXPECT_DOUBLE_EQ(clumps->sphere_steps(1000.0, 1.0), 3 * 5 * 1000 * 0.965);
}

} // namespace
