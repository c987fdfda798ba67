#include "fem/shell_analysis.hpp"
#include "fem/shell_directors.hpp"
#include "fem/shell_mesh_generators.hpp"
#include "materials/linear_elastic.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace grainload::fem {
namespace {

constexpr double kPi = std::numbers::pi;

// Closed 2 x 3 x 4 box: every grid point of the surface once, 2 (nx ny + nx nz + ny nz)
// quads, outward normals; the open box lacks the top's quads and interior nodes.
TEST(BoxGenerator, CountsSetsAndOutwardNormals) {
    const ShellMesh closed = make_box(2.0, 3.0, 4.0, 2, 3, 4, true, 0.01);
    EXPECT_EQ(closed.node_count(), 3 * 4 * 5 - 1 * 2 * 3);
    EXPECT_EQ(closed.element_count(), 2 * (6 + 8 + 12));
    EXPECT_NO_THROW(closed.validate());
    const Vec3 centre(1.0, 1.5, 2.0);
    for (const ShellElement& e : closed.elements()) {
        Vec3 middle = Vec3::Zero();
        for (const Index n : e.nodes) {
            middle += 0.25 * closed.node(n);
        }
        EXPECT_GT(element_normal(closed, e).dot(middle - centre), 0.0);
    }
    EXPECT_EQ(closed.node_set("bottom").size(), 3u * 4u);
    EXPECT_EQ(closed.node_set("bottom_edge").size(), 2u * (2u + 3u));
    EXPECT_EQ(closed.element_set("top").size(), 6u);
    for (const Index n : closed.node_set("x1")) {
        EXPECT_EQ(closed.node(n).x(), 2.0);
    }
    const ShellMesh open = make_box(2.0, 3.0, 4.0, 2, 3, 4, false, 0.01);
    EXPECT_EQ(open.node_count(), closed.node_count() - 1 * 2);
    EXPECT_EQ(open.element_count(), closed.element_count() - 6);
    EXPECT_EQ(open.node_set("top_edge").size(), 2u * (2u + 3u));
    EXPECT_NO_THROW(open.validate());
}

// The box's edges are fold nodes: 4 (nx-1) + 4 (ny-1) + 4 (nz-1) + 8 corners when closed; an
// open box loses the top perimeter except its corners. There each element's director is its
// face normal exactly; elsewhere the averaged normal (here also the face normal).
TEST(ShellDirectors, BoxEdgesAreFoldsWithFaceNormals) {
    const ShellMesh closed = make_box(2.0, 3.0, 4.0, 2, 3, 4, true, 0.01);
    EXPECT_EQ(fold_nodes(closed).size(), std::size_t{4 * 1 + 4 * 2 + 4 * 3 + 8});
    const ShellMesh open = make_box(2.0, 3.0, 4.0, 2, 3, 4, false, 0.01);
    EXPECT_EQ(fold_nodes(open).size(), std::size_t{4 * 1 + 4 * 2 + 4 * 3 + 8 - 2 * 1 - 2 * 2});
    const ElementDirectors directors = element_directors(closed);
    for (Index e = 0; e < closed.element_count(); ++e) {
        const Vec3 face = element_normal(closed, closed.element(e));
        for (const Vec3& v : directors[static_cast<std::size_t>(e)]) {
            EXPECT_LT((v - face).norm(), 1e-15);
        }
    }
}

// The threshold compares each normal with the average: a 90 deg fold deviates 45 deg, so a
// fold angle of 50 deg averages it; smooth generated surfaces (exact normals) never fold, and
// there the element directors are the nodal normals bit for bit.
TEST(ShellDirectors, ThresholdAndSmoothSurfaces) {
    ShellMesh box = make_box(1.0, 1.0, 1.0, 2, 2, 2, true, 0.01);
    box.set_fold_angle(50.0 * kPi / 180.0);
    EXPECT_EQ(fold_nodes(box).size(), 8u); // corners: normals 54.7 deg from their average
    box.set_fold_angle(kPi);
    EXPECT_TRUE(fold_nodes(box).empty());
    const ShellMesh cylinder = make_cylinder(1.0, 1.0, 0.0, 0.5 * kPi, 2, 2, 0.01);
    EXPECT_TRUE(fold_nodes(cylinder).empty()); // 45 deg per element, but exact normals
    const ElementDirectors directors = element_directors(cylinder);
    const std::vector<Vec3> nodal = cylinder.nodal_normals();
    for (Index e = 0; e < cylinder.element_count(); ++e) {
        for (std::size_t k = 0; k < 4; ++k) {
            EXPECT_EQ(directors[static_cast<std::size_t>(e)][k],
                      nodal[static_cast<std::size_t>(cylinder.element(e).nodes[k])]);
        }
    }
}

// Without exact normals (as from Gmsh) a coarse cylinder, 22.5 deg between neighbouring
// facets, stays smooth at the default 20 deg: each facet normal is 11.25 deg off the average
// at the nodes between facets. A 10 deg threshold folds exactly those (n_phi - 1)(n_y + 1)
// nodes; the nodes on the straight edges see parallel facets only.
TEST(ShellDirectors, CoarseFacetedCylinderStaysSmooth) {
    const ShellMesh exact = make_cylinder(1.0, 1.0, 0.0, 0.5 * kPi, 4, 2, 0.01);
    ShellMesh faceted;
    for (const Vec3& x : exact.nodes()) {
        faceted.add_node(x);
    }
    for (const ShellElement& e : exact.elements()) {
        faceted.add_element(e.nodes, e.thickness);
    }
    EXPECT_TRUE(fold_nodes(faceted).empty());
    faceted.set_fold_angle(10.0 * kPi / 180.0);
    EXPECT_EQ(fold_nodes(faceted).size(), std::size_t{3 * 3});
}

// A finite rigid rotation of a folded body strains nothing: the one nodal rotation turns
// every director attached to the node, so the faces stay joined at the fold. Internal forces
// stay at round-off (1e-12 of E t L, a strain of 1e-12) and the directors are R V0.
TEST(ShellDirectors, RigidRotationOfFoldedBoxIsStrainFree) {
    const double young = 2e11;
    const materials::LinearElastic material(
        materials::ElasticConstants::from_young(7850.0, young, 0.3));
    ShellAnalysis analysis(make_box(1.0, 0.8, 0.6, 3, 3, 2, true, 0.01), material,
                           Kinematics::total_lagrangian, 2);
    const ShellMesh& mesh = analysis.mesh();
    const Vec3 axis = Vec3(1.0, 2.0, 3.0).normalized();
    const double angle = 1.0; // rad
    const Mat3 r = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    Eigen::VectorXd increment = Eigen::VectorXd::Zero(6 * mesh.node_count());
    for (Index n = 0; n < mesh.node_count(); ++n) {
        increment.segment<3>(6 * n) = (r - Mat3::Identity()) * mesh.node(n);
        increment.segment<3>(6 * n + 3) = angle * axis;
    }
    const ElementDirectors initial = element_directors(mesh);
    analysis.update_state(increment);
    Eigen::VectorXd internal;
    analysis.assemble(nullptr, internal);
    EXPECT_LT(internal.cwiseAbs().maxCoeff(), 1e-12 * young * 0.01 * 1.0);
    for (Index e = 0; e < mesh.element_count(); ++e) {
        for (int k = 0; k < 4; ++k) {
            const Vec3 expected =
                r * initial[static_cast<std::size_t>(e)][static_cast<std::size_t>(k)];
            EXPECT_LT((analysis.director(e, k) - expected).norm(), 1e-14);
        }
    }
}

} // namespace
} // namespace grainload::fem
