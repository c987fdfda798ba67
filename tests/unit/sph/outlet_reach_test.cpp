// Where material can get to before the run (sph/outlet_reach.hpp), on a 2D bin 0.2 m wide and
// 0.3 m tall (walls of three layers at 10 mm, open at the top) holding a fill 0.1 m deep.
#include "sph/outlet_reach.hpp"
#include "sph/rigid_wall.hpp"

#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

constexpr double kSpacing = 0.01;

struct Bin {
    ParticleSet particles;
    std::vector<Wall> walls;
};

/// The fill at rest (or moving at `velocity`) in the bin; the floor leaves at 1 s when
/// `gate` (a wall removed at a time does not hold material).
Bin bin(const Vec3& velocity, bool gate) {
    Bin b;
    for (int i = 0; i < 17; ++i) {
        for (int j = 0; j < 9; ++j) {
            b.particles.add(Vec3(0.02 + kSpacing * i, 0.02 + kSpacing * j, 0.0), velocity, 1.0,
                            1500.0, 0, 0, 0);
        }
    }
    struct Side {
        const char* name;
        Vec3 origin;
        Vec3 edge;
        Vec3 normal;
    };
    const Side sides[] = {{"floor", Vec3::Zero(), Vec3(0.2, 0.0, 0.0), Vec3::UnitY()},
                          {"left", Vec3::Zero(), Vec3(0.0, 0.3, 0.0), Vec3::UnitX()},
                          {"right", Vec3(0.2, 0.0, 0.0), Vec3(0.0, 0.3, 0.0), -Vec3::UnitX()}};
    for (const Side& s : sides) {
        const int k = static_cast<int>(b.walls.size());
        b.walls.push_back(
            add_wall(b.particles, s.name, k, 1 + k,
                     plane_wall_points(s.origin, s.edge, Vec3::Zero(), s.normal, kSpacing, 3, 2),
                     kSpacing, 1.0, 2));
    }
    if (gate) {
        b.walls[0].removal_time = 1.0;
    }
    return b;
}

const Vec3 kGravity(0.0, -9.81, 0.0);

io::Region box(double x0, double y0, double x1, double y1) {
    return io::Region::box(Vec3(x0, y0, 0.0), Vec3(x1, y1, 0.0), 2);
}

// At rest, the fill reaches the bin's floor but not the space above it in the bin (nothing
// climbs), nor a bin beside the walls at floor level, nor a plane sink 0.5 m below the floor.
// Moving upwards it may climb: over the walls and down beside them to the plane sink. With the
// floor a gate (removed at 1 s) it falls through to the sink, and still does not climb.
TEST(OutletReach, TheFloodStopsAtWallsThatStayAndDoesNotClimbFromRest) {
    const io::Region floor = box(0.05, 0.0, 0.15, 0.015);
    const io::Region above = box(0.05, 0.2, 0.15, 0.25);
    const io::Region beside = box(0.3, -0.1, 0.4, -0.05);
    const io::Region below = io::Region::half_space(Vec3(0.0, -0.5, 0.0), -Vec3::UnitY(), 2);
    const std::vector<io::Region> regions{floor, above, beside, below};
    const Bin rest = bin(Vec3::Zero(), false);
    const ReachMap still(rest.particles, rest.walls, SourceSet(), regions, kGravity, kSpacing, 2,
                         -1);
    EXPECT_TRUE(still.reaches(floor));
    EXPECT_FALSE(still.reaches(above));
    EXPECT_FALSE(still.reaches(beside));
    EXPECT_FALSE(still.reaches(below));

    const Bin thrown = bin(Vec3(0.0, 1.0, 0.0), false);
    const ReachMap climbing(thrown.particles, thrown.walls, SourceSet(), regions, kGravity,
                            kSpacing, 2, -1);
    EXPECT_TRUE(climbing.reaches(above));
    EXPECT_TRUE(climbing.reaches(beside));
    EXPECT_TRUE(climbing.reaches(below));

    const Bin gated = bin(Vec3::Zero(), true);
    const ReachMap opened(gated.particles, gated.walls, SourceSet(), regions, kGravity, kSpacing, 2,
                          -1);
    EXPECT_TRUE(opened.reaches(below));
    EXPECT_FALSE(opened.reaches(above));
    // The flood of a body that has no particles and no source reaches nothing.
    const ReachMap empty(rest.particles, rest.walls, SourceSet(), regions, kGravity, kSpacing, 2,
                         7);
    EXPECT_FALSE(empty.reaches(floor));
}

} // namespace
} // namespace grainload::sph
