// A DEM wall due at a stated time leaves with the step whose end reaches that time, also when
// the driver's cut to an output instant leaves the step's end an ulp short of it.

#include "support/dem_scene.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace {

using namespace grainload;
using grainload::testing::dem_model;
using grainload::testing::glass;

/// A bead resting on a floor that leaves at 0.1 s.
std::unique_ptr<dem::DemModel> floor_removed_at_a_tenth() {
    return dem_model("[case]\nend_time = \"1 s\"\n" + glass() +
                     "[dem]\n[dem.contact]\nlaw = \"hertz_mindlin\"\n[[dem.body]]\nname = "
                     "\"bead\"\nmaterial = \"glass\"\nradius = \"5 mm\"\ncentre = \"0 0 5 mm\"\n"
                     "[[dem.wall]]\nname = \"floor\"\ntype = \"plane\"\npoint = \"0 0 0 m\"\n"
                     "normal = \"0 0 1\"\nremove_at = \"0.1 s\"\n");
}

// 0.1 s as the sum of steps that land on it can come out 0.09999999999999999: that step's end
// is the stated time (the SPH gates and the driver's end take it so), and the wall leaves with
// it; a step ending a millionth of the time short does not reach it.
TEST(DemWallRemoval, AStepEndingAnUlpShortOfRemoveAtReachesIt) {
    auto short_by_an_ulp = floor_removed_at_a_tenth();
    short_by_an_ulp->advance(0.0, std::nextafter(0.1, 0.0));
    EXPECT_TRUE(short_by_an_ulp->walls()[0].removed);
    auto short_by_a_millionth = floor_removed_at_a_tenth();
    short_by_a_millionth->advance(0.0, 0.1 * (1.0 - 1e-6));
    EXPECT_FALSE(short_by_a_millionth->walls()[0].removed);
}

} // namespace
