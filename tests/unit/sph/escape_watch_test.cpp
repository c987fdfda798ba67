// The escape watchdog (sph/escape_watch.hpp) on hand-placed particles.

#include "sph/escape_watch.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

constexpr double kG = 9.81;

std::string name_of(int body) {
    return body == 0 ? "sand" : "wall";
}

/// A 1 m cube of sand particles at rest on [0, 1]^3 (corners and centre suffice for the box)
/// and, when `wall`, a floor particle at z = 0.
ParticleSet cube(bool wall = false) {
    ParticleSet p;
    for (const Vec3& x : {Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(0.5, 0.5, 0.5)}) {
        p.add(x, Vec3::Zero(), 1.0, 1000.0, 0, 0, 0);
    }
    if (wall) {
        p.add_wall_particle(Vec3(0.5, 0.5, 0.0), Vec3::Zero(), 1.0, 1000.0, 1, 0);
    }
    return p;
}

// The box is [0, 1]^3 widened by half its largest extent: [-0.5, 1.5]^3, H = 2 m. A particle
// 1 m below it (z = -1.5) may fall at up to 2 sqrt(2 g (H + d)) = 2 sqrt(2 g 3 m) = 15.3 m/s.
TEST(EscapeWatch, AFastParticleFarOutsideIsNamedWithItsSpeed) {
    ParticleSet p = cube();
    const EscapeWatch watch(p, Vec3(0, 0, -kG), 3);
    p.position[2] = Vec3(0.5, 0.5, -1.5);
    p.velocity[2] = Vec3(0, 0, -100.0);
    const auto diagnosis = watch.check(p, name_of);
    ASSERT_TRUE(diagnosis.has_value());
    EXPECT_NE(diagnosis->find("particle 2 (body sand) escaped the scene"), std::string::npos)
        << *diagnosis;
    EXPECT_NE(diagnosis->find("1 m outside the scene box"), std::string::npos) << *diagnosis;
    EXPECT_NE(diagnosis->find("moving outward at 100 m/s"), std::string::npos) << *diagnosis;
    EXPECT_NE(diagnosis->find("faster than the 15.3"), std::string::npos) << *diagnosis;
    EXPECT_EQ(diagnosis->find('\n'), std::string::npos); // one line
}

// Free fall is never an escape: a particle dropped from rest at the top of the box and
// falling 10 m below it has v = sqrt(2 g (H + d)) exactly, half the limit; moving inward or
// sideways at any speed is not leaving either.
TEST(EscapeWatch, FreeFallAndInwardMotionAreNotEscapes) {
    ParticleSet p = cube();
    const EscapeWatch watch(p, Vec3(0, 0, -kG), 3);
    const double fall = 1.5 - (-0.5 - 10.0); // from z = 1.5 to z = -10.5
    p.position[2] = Vec3(0.5, 0.5, -10.5);
    p.velocity[2] = Vec3(0, 0, -std::sqrt(2.0 * kG * fall));
    EXPECT_FALSE(watch.check(p, name_of).has_value());
    p.velocity[2] = Vec3(1e4, 0, 1e3); // far below, flying sideways and up
    EXPECT_FALSE(watch.check(p, name_of).has_value());
    p.position[2] = Vec3(1.4, 0.5, 0.5); // inside the margin, at any speed
    p.velocity[2] = Vec3(1e6, 0, 0);
    EXPECT_FALSE(watch.check(p, name_of).has_value());
}

// A wall carries the scene with it: sand next to a floor that has moved 100 m away is inside
// the grown box, and the wall's speed raises v0.
TEST(EscapeWatch, MovingWallsTakeTheBoxAndTheirSpeedWithThem) {
    ParticleSet p = cube(true);
    const EscapeWatch watch(p, Vec3(0, 0, -kG), 3);
    p.position[3] = Vec3(100.5, 0.5, 0.0);
    p.velocity[3] = Vec3(50.0, 0, 0);
    p.position[2] = Vec3(100.5, 0.5, 0.2);
    p.velocity[2] = Vec3(50.0, 0, 0);
    EXPECT_FALSE(watch.check(p, name_of).has_value());
    // Now 10 m beyond the wall: the limit is 2 sqrt(50^2 + 2 g (H + d)) > 100 m/s.
    p.position[2] = Vec3(111.0, 0.5, 0.2);
    p.velocity[2] = Vec3(99.0, 0, 0);
    EXPECT_FALSE(watch.check(p, name_of).has_value());
    p.velocity[2] = Vec3(150.0, 0, 0);
    EXPECT_TRUE(watch.check(p, name_of).has_value());
}

// Plane strain: z is not a direction to escape in, and the box is the x-y one.
TEST(EscapeWatch, PlaneStrainIgnoresZ) {
    ParticleSet p;
    for (const Vec3& x : {Vec3(0, 0, 0), Vec3(1, 1, 0)}) {
        p.add(x, Vec3::Zero(), 1.0, 1000.0, 0, 0, 0);
    }
    const EscapeWatch watch(p, Vec3(0, -kG, 0), 2);
    p.velocity[1] = Vec3(0, 0, 1e6);
    EXPECT_FALSE(watch.check(p, name_of).has_value());
    p.position[1] = Vec3(5, 1, 0);
    p.velocity[1] = Vec3(1e3, 0, 0);
    EXPECT_TRUE(watch.check(p, name_of).has_value());
}

} // namespace
} // namespace grainload::sph
