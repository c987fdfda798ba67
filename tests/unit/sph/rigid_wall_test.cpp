#include "sph/rigid_wall.hpp"

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
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
    RigidWall wall =
        add_rigid_wall(particles, "plate", 0, 5, {Vec3(1, 0, 0), Vec3(-1, 0, 0)}, 0.1, 1.0, 3);
    EXPECT_TRUE(particles.is_wall(0));
    wall.velocity = Vec3(0.0, 0.0, 2.0);
    wall.angular_velocity = Vec3(0.0, 0.0, 0.5 * std::numbers::pi);
    for (int k = 0; k < 10; ++k) {
        move_rigid_wall(particles, wall, 0.1);
    }
    EXPECT_LT((particles.position[0] - Vec3(0.0, 1.0, 2.0)).norm(), 1e-12);
    EXPECT_LT((particles.velocity[0] - Vec3(-0.5 * std::numbers::pi, 0.0, 2.0)).norm(), 1e-12);
}

TEST(RigidWall, WallForcesFileHasOneRowPerWallAndInstant) {
    const auto directory = std::filesystem::temp_directory_path() / "grainload_wall_test";
    RigidWall wall;
    wall.name = "floor";
    wall.force = Vec3(1.0, 2.0, 3.0);
    {
        WallForceWriter writer(directory.string());
        writer.write(0.5, {wall});
    }
    std::ifstream in(directory / "wall_forces.csv");
    std::string header;
    std::string row;
    std::getline(in, header);
    std::getline(in, row);
    EXPECT_EQ(header.rfind("time_s,wall,force_x_N", 0), 0u);
    EXPECT_EQ(row, "0.5,floor,1,2,3,0,0,0");
}

} // namespace
} // namespace grainload::sph
