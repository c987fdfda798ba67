#include "sph/symmetry.hpp"

#include <array>
#include <gtest/gtest.h>
#include <vector>

namespace grainload::sph {
namespace {

// A shift by a period of 1 m (or 0.5 m) and a reflection in a coordinate plane each change one
// coordinate by an exact binary fraction here: the positions compare exactly.
constexpr double kExact = 0.0;

TEST(Periodic, ParticlesNearEitherEndSeeTheOthersOnePeriodBeyond) {
    const std::array<PeriodicAxis, 1> periodic{PeriodicAxis{0, 0.0, 1.0}};
    const double cutoff = 0.125;
    // near the lower end, near the upper end, in the middle, a wall particle near the lower end
    // (mirrored across no symmetry plane: periodic images are every particle's)
    const std::vector<Vec3> x{
        {0.0625, 0.5, 0.0}, {0.9375, 0.25, 0.0}, {0.5, 0.5, 0.0}, {0.03125, 0.0, 0.0}};
    const std::vector<char> wall{0, 0, 0, 1};
    const std::vector<MirrorMask> allowed{7, 7, 7, 0};
    const auto images = select_images({}, periodic, x, wall, allowed, cutoff);
    ASSERT_EQ(images.size(), 3U);
    const ImageFrame frame = image_frame({}, periodic);
    // The wall particle's image first: one period above, as the grains near the upper end need.
    EXPECT_EQ(images[0].source, 3);
    EXPECT_EQ(images[0].mask, 0);
    EXPECT_EQ(image_position(x[3], images[0], frame), Vec3(1.03125, 0.0, 0.0));
    EXPECT_EQ(images[1].source, 0);
    EXPECT_EQ((image_position(x[0], images[1], frame) - Vec3(1.0625, 0.5, 0.0)).norm(), kExact);
    EXPECT_EQ(images[2].source, 1);
    EXPECT_EQ((image_position(x[1], images[2], frame) - Vec3(-0.0625, 0.25, 0.0)).norm(), kExact);
}

// A periodic axis and a symmetry plane meet at an edge: a particle near both has the image of
// each and the image of the image (shifted and reflected).
TEST(Periodic, APeriodicAxisBesideASymmetryPlaneGivesTheImageOfTheImage) {
    const std::array<SymmetryPlane, 1> planes{SymmetryPlane{1, 0.0, 1}};
    const std::array<PeriodicAxis, 1> periodic{PeriodicAxis{0, 0.0, 0.5}};
    const std::vector<Vec3> x{{0.46875, 0.0625, 0.0}};
    const auto images =
        select_images(planes, periodic, x, std::vector<char>{0}, std::vector<MirrorMask>{7}, 0.125);
    ASSERT_EQ(images.size(), 3U);
    const ImageFrame frame = image_frame(planes, periodic);
    std::vector<Vec3> at;
    for (const GhostImage& image : images) {
        at.push_back(image_position(x[0], image, frame));
    }
    EXPECT_EQ(at[0], Vec3(-0.03125, 0.0625, 0.0));  // shifted down
    EXPECT_EQ(at[1], Vec3(0.46875, -0.0625, 0.0));  // reflected
    EXPECT_EQ(at[2], Vec3(-0.03125, -0.0625, 0.0)); // both
}

TEST(Periodic, WrapBringsMaterialBackIntoThePeriodAndLeavesWalls) {
    const std::array<PeriodicAxis, 1> periodic{PeriodicAxis{1, -0.5, 0.5}};
    std::vector<Vec3> x{{0.0, 0.5, 0.0}, {0.0, -0.625, 0.0}, {0.0, 0.25, 0.0}, {0.0, 0.75, 0.0}};
    const std::vector<char> wall{0, 0, 0, 1};
    wrap_periodic(x, wall, periodic);
    EXPECT_EQ(x[0].y(), -0.5); // max belongs to the next period: [min, max)
    EXPECT_EQ(x[1].y(), 0.375);
    EXPECT_EQ(x[2].y(), 0.25);
    EXPECT_EQ(x[3].y(), 0.75); // a wall particle stays where its wall puts it
    const std::vector<Vec3> wrapped = x;
    wrap_periodic(x, wall, periodic); // inside the period: nothing moves again
    EXPECT_EQ(x, wrapped);
}

TEST(Periodic, DisplacementsAcrossTheSeamAreTheNearestImages) {
    const std::array<PeriodicAxis, 1> periodic{PeriodicAxis{0, 0.0, 2.0}};
    // A particle that moved 0.25 m up across the seam at x = 2 m now sits 1.75 m below its start.
    EXPECT_EQ(nearest_image(Vec3(-1.75, 0.5, 0.0), periodic), Vec3(0.25, 0.5, 0.0));
    EXPECT_EQ(nearest_image(Vec3(0.75, 0.0, 0.0), periodic), Vec3(0.75, 0.0, 0.0));
    EXPECT_EQ(nearest_image(Vec3(4.5, 0.0, 3.0), periodic), Vec3(0.5, 0.0, 3.0));
}

} // namespace
} // namespace grainload::sph
