#include "io/case_table.hpp"
#include "sph/rigid_wall.hpp"
#include "sph/sph_case_reader.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <numbers>
#include <string>

namespace grainload::sph {
namespace {

TEST(RigidWall, PlaneWallHasLayersBehindTheSurface) {
    const auto points = plane_wall_points(Vec3::Zero(), Vec3(1.0, 0.0, 0.0), Vec3::Zero(),
                                          Vec3(0.0, 1.0, 0.0), 0.1, 3, 2);
    ASSERT_EQ(points.size(), 33u); // 11 points per layer, 3 layers
    for (const Vec3& x : points) {
        EXPECT_LT(x.y(), 0.0); // behind the surface, away from the material
        EXPECT_GT(x.y(), -0.3);
    }
}

TEST(RigidWall, OpenBoxLeavesTheTopFree) {
    const Vec3 lower(0.0, 0.0, 0.0);
    const Vec3 upper(1.0, 1.0, 0.0);
    const auto points = box_wall_points(lower, upper, 0.1, 2, 2, true);
    for (const Vec3& x : points) {
        const bool inside = x.x() > 0.0 && x.x() < 1.0 && x.y() > 0.0 && x.y() < 1.0;
        EXPECT_FALSE(inside);
        EXPECT_LE(x.y(), 1.0);
    }
    EXPECT_GT(points.size(), 60u);
}

TEST(RigidWall, RigidMotionRotatesExactlyAboutTheMovingCentre) {
    ParticleSet particles;
    Wall wall = add_wall(particles, "plate", 0, 5, {Vec3(1, 0, 0), Vec3(-1, 0, 0)}, 0.1, 1.0, 3);
    EXPECT_TRUE(particles.is_wall(0));
    const Vec3 omega(0.0, 0.0, 0.5 * std::numbers::pi);
    attach_rigid_motion(particles, wall, Vec3(0.0, 0.0, 2.0), omega);
    ASSERT_TRUE(wall.moves());
    for (int k = 0; k < 10; ++k) {
        wall.driver->move(particles, wall, 0.1 * k, 0.1);
    }
    EXPECT_LT((particles.position[0] - Vec3(0.0, 1.0, 2.0)).norm(), 1e-12);
    EXPECT_LT((particles.velocity[0] - Vec3(-0.5 * std::numbers::pi, 0.0, 2.0)).norm(), 1e-12);
    // The wall's velocity anywhere from one particle's velocity and angular velocity: the rigid
    // field v + omega x (x - centre), here at the centre itself (0, 0, 2).
    const Vec3 at_centre = wall.velocity_at(particles, 0, Vec3(0.0, 0.0, 2.0));
    EXPECT_LT((at_centre - Vec3(0.0, 0.0, 2.0)).norm(), 1e-12);
    EXPECT_LT((wall.centre - Vec3(0.0, 0.0, 2.0)).norm(), 1e-12);
}

// A piecewise-linear history has a piecewise-quadratic integral; the wall moves by the exact
// integral over each step, so a step size that straddles the breakpoints still ends on it.
TEST(RigidWall, VelocityHistoryMovesTheWallByItsIntegral) {
    const auto document = io::CaseDocument::from_string(R"(
[sph]
[[sph.wall]]
name = "piston"
type = "plane"
origin = "0 0 0 m"
edge_u = "1 0 0 m"
edge_v = "0 1 0 m"
normal = "0 0 1"
layers = 1
velocity_history = [["0 s", "0 0 0 m/s"], ["0.5 s", "0 0 0.1 m/s"], ["0.8 s", "0.2 0 0.1 m/s"]]
angular_velocity_history = [["0.2 s", "0 0 0 rad/s"], ["0.6 s", "0 0 2 rad/s"]]
)",
                                                        "walls.toml");
    ParticleSet particles;
    auto walls = read_rigid_walls(document->root().table("sph"), particles, 3, 0.5, 0.5, 1);
    ASSERT_EQ(walls.size(), 1u);
    Wall& wall = walls[0];
    auto& motion = dynamic_cast<RigidMotion&>(*wall.driver);
    const Vec3 start = wall.centre;
    const Vec3 arm0 = particles.position[0] - start;
    const double dt = 0.0123; // not a divisor of the breakpoints
    double t = 0.0;
    while (t < 1.2) {
        wall.driver->move(particles, wall, t, dt);
        t += dt;
    }
    // Integral of the velocity up to t: 0.025 (ramp) + 0.3 * 0.1 + (t - 0.8) * 0.1 in z;
    // 0.03 + (t - 0.8) * 0.2 in x; the angle is 0.4 + 2 (t - 0.6) rad about z.
    const Vec3 travelled(0.03 + (t - 0.8) * 0.2, 0.0, 0.025 + 0.03 + (t - 0.8) * 0.1);
    EXPECT_LT((wall.centre - start - travelled).norm(), 1e-13);
    const Mat3 turned = Eigen::AngleAxisd(0.4 + 2.0 * (t - 0.6), Vec3::UnitZ()).matrix();
    EXPECT_LT((particles.position[0] - wall.centre - turned * arm0).norm(), 1e-12);
    EXPECT_LT((motion.velocity - Vec3(0.2, 0.0, 0.1)).norm(), 1e-15);
    EXPECT_LT((history_integral(motion.velocity_history, 0.0, 0.5) - Vec3(0, 0, 0.025)).norm(),
              1e-15);
    EXPECT_LT((history_value(motion.velocity_history, 0.25) - Vec3(0, 0, 0.05)).norm(), 1e-15);
}

TEST(RigidWall, WallForcesFileHasOneRowPerWallAndInstant) {
    Wall wall;
    wall.name = "floor";
    wall.force = Vec3(1.0, 2.0, 3.0);
    std::vector<Wall> walls{wall, wall};
    walls[1].name = "door";
    walls[1].moment = Vec3(0.0, -4.5, 0.0);
    EXPECT_EQ(std::string(kWallForcesHeader).rfind("time_s,wall,force_x_N", 0), 0u);
    EXPECT_EQ(wall_force_rows(0.5, walls), "0.5,floor,1,2,3,0,0,0\n0.5,door,1,2,3,0,-4.5,0\n");
}

} // namespace
} // namespace grainload::sph
