// A sphere rolling down a tessellated incline: the mesh wall carries it as the plane does,
// across the triangles' edges, and both roll at (5/7) g sin theta.

#include "support/dem_scene.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <unistd.h>

namespace {

using namespace grainload;
using grainload::testing::dem_model;
using grainload::testing::glass;
using grainload::testing::step_until;

constexpr double kG = 9.81;

/// The plane z = 0 over x in [-0.05, 0.25] m, y in [-0.05, 0.05] m as an ASCII STL of 10 mm
/// squares, each cut along a diagonal that alternates from square to square.
std::string write_incline_mesh() {
    const auto path = std::filesystem::temp_directory_path() /
                      ("grainload_incline_" + std::to_string(::getpid()) + ".stl");
    std::ofstream out(path);
    out << "solid incline\n";
    auto facet = [&out](const Vec3& a, const Vec3& b, const Vec3& c) {
        out << "facet normal 0 0 1\nouter loop\n";
        for (const Vec3& v : {a, b, c}) {
            out << "vertex " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
        }
        out << "endloop\nendfacet\n";
    };
    for (int j = -5; j < 5; ++j) {
        for (int i = -5; i < 25; ++i) {
            const Vec3 a(0.01 * i, 0.01 * j, 0.0);
            const Vec3 b = a + Vec3(0.01, 0, 0);
            const Vec3 c = a + Vec3(0.01, 0.01, 0);
            const Vec3 d = a + Vec3(0, 0.01, 0);
            if ((i + j) % 2 == 0) {
                facet(a, b, c);
                facet(a, c, d);
            } else {
                facet(a, b, d);
                facet(b, c, d);
            }
        }
    }
    out << "endsolid incline\n";
    return path.string();
}

/// One glass sphere of radius 5 mm on the incline z = 0 (gravity tilted by `degrees` about y),
/// free to turn or not, wall friction 0.5: `wall` is the [[dem.wall]] table's body.
std::unique_ptr<dem::DemModel> sphere_on(double degrees, const std::string& wall,
                                         bool rotation = true) {
    const double theta = degrees * std::numbers::pi / 180.0;
    const std::string gravity = std::to_string(kG * std::sin(theta)) + " 0 " +
                                std::to_string(-kG * std::cos(theta)) + " m/s^2";
    return dem_model("[case]\nend_time = \"1 s\"\ngravity = \"" + gravity + "\"\n" + glass() +
                     "[dem]\n[dem.contact]\nlaw = \"linear\"\nnormal_stiffness = \"10000 N/m\"\n"
                     "gamma_n = \"400 1/s\"\ngamma_t = \"400 1/s\"\nwall_friction = 0.5\n"
                     "[[dem.body]]\nname = \"ball\"\nmaterial = \"glass\"\nradius = \"5 mm\"\n"
                     "centre = \"0.003 0.002 0.005 m\"\nrotation = " +
                     (rotation ? "true" : "false") +
                     "\n[[dem.wall]]\n"
                     "name = \"slope\"\n" +
                     wall);
}

// The rolling sphere crosses about 25 triangle edges in 0.3 s (0.11 m at 10 mm squares). Over a
// triangle it sits on one face; over an edge or a corner the triangles sharing it count once;
// a contact moving onto the next triangle takes over its springs. So the mesh wall gives the
// plane wall's motion to round-off (bound 1e-9 m on 0.11 m: the two compute the overlap by
// different operations), and both the rolling acceleration (5/7) g sin theta within 0.5 % (the
// incline's own bound). A spring restarted at each edge lets the contact slip there until it
// stretches again, which puts the sphere micrometres off the plane's run (measured 2.7e-6 m).
TEST(MeshWall, ASphereRollsDownATessellatedInclineAsDownThePlane) {
    const std::string mesh = write_incline_mesh();
    auto plane = sphere_on(20.0, "type = \"plane\"\npoint = \"0 0 0 m\"\nnormal = \"0 0 1\"\n");
    auto tessellated = sphere_on(20.0, "type = \"mesh\"\nfile = \"" + mesh + "\"\n");
    std::filesystem::remove(mesh);
    double t = step_until(*plane, 0.0, 0.1, [](double) {});
    step_until(*tessellated, 0.0, 0.1, [](double) {});
    const double v1 = tessellated->grains().velocity[0].x();
    step_until(*plane, t, 0.3, [](double) {});
    t = step_until(*tessellated, t, 0.3, [](double) {});
    const auto& on_mesh = tessellated->grains();
    const auto& on_plane = plane->grains();
    std::cout << "travelled " << on_mesh.position[0].x() << " m; mesh - plane "
              << (on_mesh.position[0] - on_plane.position[0]).transpose() << " m\n";
    EXPECT_GT(on_mesh.position[0].x(), 0.1);
    EXPECT_LT((on_mesh.position[0] - on_plane.position[0]).norm(), 1e-9);
    EXPECT_LT((on_mesh.angular_velocity[0] - on_plane.angular_velocity[0]).norm(), 1e-6);
    const double expected = 5.0 / 7.0 * kG * std::sin(20.0 * std::numbers::pi / 180.0);
    EXPECT_NEAR((on_mesh.velocity[0].x() - v1) / 0.2, expected, 0.005 * expected);
}

// Below the friction angle a sphere that cannot turn sticks on the tessellated incline as on the
// plane (incline test: within 1e-3 of its radius from 0.1 s to 0.3 s): its tangential spring
// holds it at rest. A spring lost at every step would leave only the dashpot, and the sphere
// would creep at m g sin(theta) / (gamma_t m) = 8.4 mm/s, 1.7 mm in 0.2 s.
TEST(MeshWall, ASphereThatCannotTurnSticksOnATessellatedIncline) {
    const std::string mesh = write_incline_mesh();
    auto model = sphere_on(20.0, "type = \"mesh\"\nfile = \"" + mesh + "\"\n", false);
    std::filesystem::remove(mesh);
    const double t = step_until(*model, 0.0, 0.1, [](double) {});
    const double settled = model->grains().position[0].x();
    step_until(*model, t, 0.3, [](double) {});
    EXPECT_LT(std::abs(model->grains().position[0].x() - settled), 1e-3 * 0.005);
    EXPECT_LT(model->grains().velocity[0].norm(), 1e-6);
}

} // namespace
