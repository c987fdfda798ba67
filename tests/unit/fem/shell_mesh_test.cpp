#include "fem/shell_mesh_generators.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <stdexcept>

namespace grainload::fem {
namespace {

TEST(ShellMesh, PlateHasCountsAndEdgeSets) {
    const ShellMesh mesh = make_plate(2.0, 1.0, 4, 2, 0.01);
    EXPECT_EQ(mesh.node_count(), 15);
    EXPECT_EQ(mesh.element_count(), 8);
    EXPECT_EQ(mesh.node_set("x0").size(), 3u);
    EXPECT_EQ(mesh.node_set("y1").size(), 5u);
    EXPECT_EQ(mesh.node_set("all").size(), 15u);
    EXPECT_NO_THROW(mesh.validate());
    for (const Vec3& n : mesh.nodal_normals()) {
        EXPECT_NEAR(n.z(), 1.0, 1e-14);
    }
}

TEST(ShellMesh, GeneratorsPlaceNodesOnTheirSurfaces) {
    const double pi = std::numbers::pi;
    const ShellMesh cylinder = make_cylinder(25.0, 25.0, 0.0, 40.0 * pi / 180.0, 6, 5, 0.25);
    for (const Vec3& x : cylinder.nodes()) {
        EXPECT_NEAR(std::hypot(x.x(), x.z()), 25.0, 1e-12);
    }
    const ShellMesh sphere = make_sphere_zone(10.0, 0.1 * pi, 0.5 * pi, 0.5 * pi, 4, 4, 0.04);
    for (const Vec3& x : sphere.nodes()) {
        EXPECT_NEAR(x.norm(), 10.0, 1e-12);
    }
    const ShellMesh cone = make_cone(2.0, 1.0, 1.0, 2.0 * pi, 8, 3, 0.01);
    for (const Vec3& x : cone.nodes()) {
        EXPECT_NEAR(std::hypot(x.x(), x.y()), 2.0 - x.z(), 1e-12);
    }
    EXPECT_NO_THROW(cylinder.validate());
    EXPECT_NO_THROW(sphere.validate());
    EXPECT_NO_THROW(cone.validate());
    // Normals point away from the axis on the generated curved surfaces.
    const auto normals = sphere.nodal_normals();
    for (std::size_t i = 0; i < normals.size(); ++i) {
        EXPECT_GT(normals[i].dot(sphere.nodes()[i]), 0.0);
    }
}

void expect_invalid(const ShellMesh& mesh, const std::string& fragment) {
    try {
        mesh.validate();
        FAIL() << "expected an invalid mesh";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

TEST(ShellMesh, ValidateNamesBadElements) {
    ShellMesh bad_id = make_plate(1.0, 1.0, 2, 2, 0.1);
    bad_id.add_element({0, 1, 4, 99}, 0.1);
    expect_invalid(bad_id, "shell element 4: unknown node id 99");

    ShellMesh zero_area = make_plate(1.0, 1.0, 2, 2, 0.1);
    zero_area.add_element({0, 1, 1, 0}, 0.1);
    expect_invalid(zero_area, "shell element 4: zero area");

    ShellMesh inverted = make_plate(1.0, 1.0, 3, 3, 0.1);
    inverted.add_element({5, 6, 10, 9}, 0.1); // duplicate of the centre element...
    ShellMesh flipped;
    for (const Vec3& x : inverted.nodes()) {
        flipped.add_node(x);
    }
    for (Index e = 0; e < 9; ++e) {
        auto nodes = inverted.element(e).nodes;
        if (e == 4) {
            std::swap(nodes[1], nodes[3]); // ...and the centre one reversed
        }
        flipped.add_element(nodes, 0.1);
    }
    expect_invalid(flipped, "shell element 4: inverted orientation");

    ShellMesh no_thickness = make_plate(1.0, 1.0, 1, 1, 0.0);
    expect_invalid(no_thickness, "shell element 0: thickness");
}

TEST(ShellMesh, UnknownSetListsKnownOnes) {
    const ShellMesh mesh = make_plate(1.0, 1.0, 1, 1, 0.1);
    try {
        (void)mesh.node_set("edge");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("x0"), std::string::npos);
    }
    EXPECT_EQ(mesh.nearest_node(Vec3(0.9, 1.1, 0.0)), 3);
}

TEST(ShellMesh, TriangleAsCollapsedQuadIsValid) {
    ShellMesh mesh;
    mesh.add_node(Vec3(0, 0, 0));
    mesh.add_node(Vec3(1, 0, 0));
    mesh.add_node(Vec3(0, 1, 0));
    mesh.add_element({0, 1, 2, 2}, 0.1);
    EXPECT_TRUE(mesh.element(0).is_triangle());
    EXPECT_NO_THROW(mesh.validate());
}

} // namespace
} // namespace grainload::fem
