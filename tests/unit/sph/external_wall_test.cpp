#include "io/case_table.hpp"
#include "materials/material_case_reader.hpp"
#include "sph/rigid_wall.hpp"
#include "sph/sph_model_reader.hpp"
#include "support/sph_scene.hpp"

#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

const char* kScene = R"(
[case]
end_time = "0.01 s"
dimension = 2
[[material]]
name = "sand"
model = "linear_elastic"
density = "1600 kg/m^3"
youngs_modulus = "5 MPa"
poisson_ratio = 0.3
[sph]
[sph.artificial_viscosity]
alpha = 0.1
[sph.contact]
stiffness = "5 MPa"
damping_ratio = 0.5
[[sph.body]]
name = "sand"
material = "sand"
spacing = "10 mm"
velocity = "0.3 -1 m/s"
[sph.body.shape]
type = "box"
min = "0 18.5 mm"
max = "100 58.5 mm"
)";

const char* kFloor = R"(
[[sph.wall]]
name = "floor"
type = "plane"
origin = "-50 0 mm"
edge_u = "200 0 mm"
normal = "0 1"
velocity = "0.1 0 m/s"
[[sph.friction]]
body = "sand"
wall = "floor"
mu_static = 0.5
mu_kinetic = 0.4
)";

void run(SphModel& model) {
    for (int step = 0; step < 200; ++step) {
        model.advance(step * 2e-5, 2e-5);
    }
}

// A wall built outside the case reader (as the coupling builds its shell walls) is the same
// wall: the plane floor of [[sph.wall]] with its rigid motion and friction, added through
// SphModel::add_wall with the same particles, normals and driver, gives the same run, bit for
// bit, sliding and sticking included.
TEST(ExternalWall, AWallAddedByTheCallerIsTheCaseFilesWall) {
    const testing::SphScene with_floor(std::string(kScene) + kFloor, "a.toml");
    const auto& from_case = with_floor.model;
    run(*from_case);

    auto bodies_only = io::CaseDocument::from_string(kScene, "b.toml");
    const io::SceneSettings scene_b = io::read_scene_settings(*bodies_only, "b");
    const auto materials_b = materials::read_material_library(bodies_only->root());
    auto model = read_sph_bodies(bodies_only->root(), scene_b, materials_b);
    const Wall& reference = from_case->solver()->walls().front();
    SphModel::WallDefinition floor;
    floor.name = "floor";
    const auto& p = from_case->particles();
    // The reference wall's initial particles: the case reader's plane at 1 layer per spacing.
    floor.points = plane_wall_points(Vec3(-0.05, 0.0, 0.0), Vec3(0.2, 0.0, 0.0), Vec3::Zero(),
                                     Vec3(0.0, 1.0, 0.0), model->spacing(),
                                     static_cast<int>(reference.count / 21), 2);
    ASSERT_EQ(static_cast<Index>(floor.points.size()), reference.count);
    floor.normals.assign(floor.points.size(), Vec3(0.0, 1.0, 0.0));
    floor.spacing = model->spacing();
    Vec3 centre = Vec3::Zero();
    for (const Vec3& x : floor.points) {
        centre += x;
    }
    centre /= static_cast<double>(floor.points.size()); // as add_wall takes the centroid
    floor.centre = centre;
    auto motion = std::make_shared<RigidMotion>();
    motion->centre = centre;
    motion->velocity = Vec3(0.1, 0.0, 0.0);
    floor.driver = motion;
    floor.friction.push_back({"sand", 0.5, 0.4});
    floor.velocities.assign(floor.points.size(), Vec3(0.1, 0.0, 0.0));
    model->add_wall(std::move(floor));
    build_sph_scene(*model, bodies_only->root());
    run(*model);
    const auto& r = model->particles();
    ASSERT_EQ(r.size(), p.size());
    for (Index i = 0; i < p.size(); ++i) {
        ASSERT_EQ(r.position[i], p.position[i]) << "particle " << i;
        ASSERT_EQ(r.velocity[i], p.velocity[i]) << "particle " << i;
    }
    EXPECT_GT(from_case->solver()->wall_contact().slipping() +
                  from_case->solver()->wall_contact().sticking(),
              0);
}

} // namespace
} // namespace grainload::sph
