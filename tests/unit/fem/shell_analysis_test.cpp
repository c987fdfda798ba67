#include "fem/newmark_integrator.hpp"
#include "fem/shell_analysis.hpp"
#include "fem/shell_mesh_generators.hpp"
#include "materials/linear_elastic.hpp"
#include "support/cantilever_strip.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <vector>

namespace grainload::fem {
namespace {

// Forces given outside the load factor (the coupling's contact forces) act in full, and
// equilibrate() re-solves at the same load factor: a cantilever strip under a tip force
// matches Euler-Bernoulli P L^3 / (3 E I) to the shear-deformation and mesh level (1 %).
TEST(ShellAnalysis, AdditionalForcesAreEquilibrated) {
    const materials::LinearElastic material(materials::ElasticConstants::from_young(1.0, 1e9, 0.0));
    ShellAnalysis analysis(make_plate(1.0, 0.1, 20, 1, 0.01), material, Kinematics::linear, 2);
    const ShellMesh& mesh = analysis.mesh();
    const double p = 1.0;
    ASSERT_TRUE(testing::load_clamped_strip(analysis, 2, -p));
    const double inertia = 0.1 * 1e-6 / 12.0;
    const double expected = p / (3.0 * 1e9 * inertia);
    const double tip = -analysis.displacement(mesh.node_set("x1")[0]).z();
    EXPECT_NEAR(tip, expected, 0.01 * expected);
    // The supports push back with the tip force (reaction = internal - applied force).
    const Eigen::VectorXd reactions = analysis.reactions();
    double vertical = 0.0;
    for (const Index n : mesh.node_set("x0")) {
        vertical += reactions(6 * n + 2);
    }
    EXPECT_NEAR(vertical, p, 1e-9);
}

// The von Mises stresses an element reports are those of its faces and mid-surface: a
// cantilever strip (nu = 0, so the bending stress is uniaxial) under a tip moment is in pure
// bending, M' = M / b per unit width in every element, so sigma = 6 M' / t^2 on both faces
// (Euler-Bernoulli; the bilinear element holds constant curvature exactly) and 0 on the
// mid-surface. No Gauss-Legendre point lies on a face: with two through the thickness the
// outermost stress is 1/sqrt(3) of the face's, which the element reported before. The section
// is linear, one solve: agreement to the solver's round-off (1e-9 of sigma).
TEST(ShellAnalysis, ElementsReportTheFacesStressesInBending) {
    const materials::LinearElastic material(materials::ElasticConstants::from_young(1.0, 1e9, 0.0));
    for (const int points : {2, 5}) {
        ShellAnalysis analysis(make_plate(1.0, 0.1, 10, 1, 0.01), material, Kinematics::linear,
                               points);
        const double moment = 1.0; // N m about y
        ASSERT_TRUE(testing::load_clamped_strip(analysis, 4, moment));
        const double width = 0.1;
        const double thickness = 0.01;
        const double face = 6.0 * (moment / width) / (thickness * thickness);
        constexpr double kRoundOff = 1e-9;
        for (const Mitc4Shell& element : analysis.elements()) {
            const ShellResultants r = element.resultants();
            EXPECT_NEAR(std::abs(r.bending(0)), moment / width, kRoundOff * moment / width);
            EXPECT_NEAR(r.von_mises_top, face, kRoundOff * face) << points;
            EXPECT_NEAR(r.von_mises_bottom, face, kRoundOff * face) << points;
            EXPECT_NEAR(r.von_mises_middle, 0.0, kRoundOff * face) << points;
        }
    }
}

// An element that cannot converge makes advance_load cut the increment back and report the
// failure instead of throwing: here a mechanism (no supports) gives a singular tangent.
TEST(ShellAnalysis, SingularModelReportsNonConvergence) {
    const materials::LinearElastic material(materials::ElasticConstants::from_young(1.0, 1e9, 0.3));
    ShellAnalysis analysis(make_plate(1.0, 1.0, 2, 2, 0.01), material, Kinematics::linear, 2);
    analysis.add_nodal_load(0, 2, 1.0);
    NewtonSettings settings;
    settings.max_cutbacks = 2;
    const StepReport report = analysis.advance_load(1.0, 1, settings);
    EXPECT_FALSE(report.converged);
    EXPECT_EQ(report.cutbacks, 3);
    EXPECT_EQ(analysis.load_factor(), 0.0);
}

// In dynamics the constrained DOFs follow their prescribed history (the tipping plate's
// lifted edge): a strip whose root is lifted rigidly with the load factor.
TEST(ShellAnalysis, NewmarkFollowsPrescribedMotion) {
    const materials::LinearElastic material(
        materials::ElasticConstants::from_young(7850.0, 2e11, 0.3));
    ShellAnalysis analysis(make_plate(1.0, 0.1, 10, 1, 0.01), material, Kinematics::linear, 2);
    const ShellMesh& mesh = analysis.mesh();
    analysis.prescribe(mesh.node_set("x0"), {0, 1, 3, 4, 5});
    analysis.prescribe(mesh.node_set("x0"), {2}, 0.05);
    NewmarkIntegrator newmark(analysis);
    newmark.initialise(Eigen::VectorXd::Zero(6 * mesh.node_count()));
    // A 5 s lift, slow beside the strip's first period (0.12 s): quasi-static, except for the
    // first-mode vibration the start of the lift excites, ~ v / omega = 0.01 / 51 m.
    for (int s = 1; s <= 100; ++s) {
        ASSERT_TRUE(newmark.step(0.05, 0.01 * s, NewtonSettings{}).converged);
    }
    for (const Index n : mesh.node_set("x0")) {
        EXPECT_NEAR(analysis.displacement(n).z(), 0.05, 1e-15);
    }
    const double tip = analysis.displacement(mesh.node_set("x1")[0]).z();
    EXPECT_NEAR(tip, 0.05, 1e-3);
}

// Node springs towards the committed state (the coupling's added mass) slow the approach to an
// equilibrium and leave the equilibrium itself unchanged. The cantilever strip above under its
// tip force P has the tip flexibility f = u* / P (u* without springs, this mesh's own answer);
// springs of total stiffness s = 1 / f along z at the tip nodes make each solve at the same
// load give u_{n+1} = f (P - s (u_{n+1} - u_n)), so u_1 = u* / (1 + f s) = u* / 2 and the error
// halves per solve: u_2 = 0.75 u* (linear algebra: 1e-9), and u* is reached to the Newton
// solver's own tolerance: it no longer iterates once the out-of-balance force, K e, is within
// its force tolerance (1e-6 of the load), which stops this sequence at e = 2^-19 u* = 1.9e-6 u*:
// 1e-5. With the stored stiffness and with assembly alike.
TEST(ShellAnalysis, NodeSpringsSlowTheApproachButNotTheEquilibrium) {
    const materials::LinearElastic material(materials::ElasticConstants::from_young(1.0, 1e9, 0.0));
    for (const bool stored : {false, true}) {
        auto strip = [&] {
            auto analysis = std::make_unique<ShellAnalysis>(make_plate(1.0, 0.1, 20, 1, 0.01),
                                                            material, Kinematics::linear, 2);
            const ShellMesh& mesh = analysis->mesh();
            analysis->prescribe(mesh.node_set("x0"), {0, 1, 2, 3, 4, 5});
            Eigen::VectorXd forces = Eigen::VectorXd::Zero(6 * mesh.node_count());
            for (const Index n : mesh.node_set("x1")) {
                forces(6 * n + 2) = -0.5;
            }
            analysis->set_additional_forces(forces);
            if (stored) {
                analysis->store_stiffness();
            }
            return analysis;
        };
        auto free = strip();
        ASSERT_TRUE(free->equilibrate(NewtonSettings{}).converged);
        const Index tip = free->mesh().node_set("x1")[0];
        const double settled = free->displacement(tip).z();
        auto sprung = strip();
        std::vector<ShellAnalysis::NodeSpring> springs;
        for (const Index n : sprung->mesh().node_set("x1")) {
            Mat3 k = Mat3::Zero();
            k(2, 2) = 0.5 * 1.0 / std::abs(settled); // half of s = P / u* at each tip node
            springs.push_back({n, k});
        }
        sprung->set_node_springs(springs);
        ASSERT_TRUE(sprung->equilibrate(NewtonSettings{}).converged);
        EXPECT_NEAR(sprung->displacement(tip).z() / settled, 0.5, 1e-9) << stored;
        ASSERT_TRUE(sprung->equilibrate(NewtonSettings{}).converged);
        EXPECT_NEAR(sprung->displacement(tip).z() / settled, 0.75, 1e-9) << stored;
        for (int n = 2; n < 40; ++n) {
            ASSERT_TRUE(sprung->equilibrate(NewtonSettings{}).converged);
        }
        EXPECT_NEAR(sprung->displacement(tip).z() / settled, 1.0, 1e-5) << stored;
    }
}

} // namespace
} // namespace grainload::fem
