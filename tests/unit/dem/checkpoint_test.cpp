// A DEM run restored from its checkpoint continues bit for bit as the uninterrupted run.

#include "support/dem_scene.hpp"

#include <cstring>
#include <gtest/gtest.h>
#include <sstream>

namespace {

using namespace grainload;
using grainload::testing::dem_model;
using grainload::testing::glass;
using grainload::testing::step_until;

/// 80 beads settling in a box with friction and damping; `dem` adds keys to [dem].
std::string settling(const std::string& dem = "") {
    return "[case]\nend_time = \"1 s\"\n" + glass() + "[dem]\n" + dem +
           "[dem.contact]\nlaw = \"hertz_mindlin\"\ngamma_n = \"100 1/s\"\n"
           "gamma_t = \"50 1/s\"\nfriction = 0.4\n"
           "[[dem.body]]\nname = \"beads\"\nmaterial = \"glass\"\nradius_min = \"4 mm\"\n"
           "radius_max = \"5 mm\"\ncount = 80\nmin = \"0 0 0 m\"\nmax = \"0.05 0.05 0.1 m\"\n"
           "[[dem.wall]]\nname = \"box\"\ntype = \"box\"\nmin = \"0 0 0 m\"\n"
           "max = \"0.05 0.05 0.2 m\"\n";
}

bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

// Stopped at 0.1 s (grains in contact, springs loaded, the neighbour list mid-use), saved and
// restored into a model built afresh from the case: 0.05 s later every position, velocity and
// spin equals the uninterrupted run's to the bit, with either integrator (the predictor-
// corrector starts each step from the state and forces the checkpoint holds).
void expect_restored_run_continues(const std::string& dem) {
    auto run = dem_model(settling(dem));
    double t = step_until(*run, 0.0, 0.1, [](double) {});
    ASSERT_GT(run->books().pair_contacts, 0);
    std::stringstream saved;
    run->write_checkpoint(saved);
    step_until(*run, t, 0.15, [](double) {});

    auto restored = dem_model(settling(dem));
    restored->read_checkpoint(saved);
    step_until(*restored, t, 0.15, [](double) {});
    EXPECT_TRUE(same_bits(run->grains().position, restored->grains().position));
    EXPECT_TRUE(same_bits(run->grains().velocity, restored->grains().velocity));
    EXPECT_TRUE(same_bits(run->grains().angular_velocity, restored->grains().angular_velocity));
    EXPECT_EQ(run->books().elastic_energy, restored->books().elastic_energy);
}

TEST(DemCheckpoint, ARestoredRunContinuesBitForBit) {
    expect_restored_run_continues("");
}

TEST(DemCheckpoint, ARestoredPredictorCorrectorRunContinuesBitForBit) {
    expect_restored_run_continues("integrator = \"predictor_corrector\"\ncorrector_passes = 3\n");
}

// Equal seeds give equal packings; another seed another one, with every grain inside its box
// and none overlapping another.
TEST(DemPlacement, SeedsRepeatAndGrainsNeitherOverlapNorLeaveTheBox) {
    const auto a = dem_model(settling());
    const auto b = dem_model(settling());
    EXPECT_TRUE(same_bits(a->grains().position, b->grains().position));
    std::string other = settling();
    other.replace(other.find("count = 80"), 10, "count = 80\nseed = 9");
    const auto c = dem_model(other);
    EXPECT_FALSE(same_bits(a->grains().position, c->grains().position));
    const auto& s = c->spheres();
    ASSERT_EQ(s.size(), 80);
    for (Index i = 0; i < s.size(); ++i) {
        EXPECT_GE(s.radius[i], 0.004);
        EXPECT_LE(s.radius[i], 0.005);
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_GE(s.position[i][axis] - s.radius[i], 0.0);
        }
        EXPECT_LE(s.position[i].x() + s.radius[i], 0.05);
        for (Index j = 0; j < i; ++j) {
            EXPECT_GE((s.position[i] - s.position[j]).norm(), s.radius[i] + s.radius[j]);
        }
    }
}

} // namespace
