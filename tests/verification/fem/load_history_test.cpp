#include "fem/shell_analysis.hpp"
#include "fem/shell_mesh_generators.hpp"
#include "fem/time_function.hpp"
#include "materials/linear_elastic.hpp"

#include <Eigen/Geometry>
#include <cstdio>
#include <gtest/gtest.h>
#include <numbers>

namespace grainload::fem {
namespace {

const materials::LinearElastic kSteel(materials::ElasticConstants::from_young(7850.0, 2.1e11, 0.3));

TEST(TimeFunction, PiecewiseLinearHeldOutsideItsPoints) {
    const TimeFunction f({{0.0, 0.0}, {0.5, 1.0}, {1.0, 0.25}});
    EXPECT_DOUBLE_EQ(f(-1.0), 0.0);
    EXPECT_DOUBLE_EQ(f(0.25), 0.5);
    EXPECT_DOUBLE_EQ(f(0.75), 0.625);
    EXPECT_DOUBLE_EQ(f(3.0), 0.25);
    const TimeFunction ramp = TimeFunction::ramp(2.0);
    EXPECT_DOUBLE_EQ(ramp(1.0), 0.5);
    EXPECT_DOUBLE_EQ(ramp(5.0), 1.0);
    EXPECT_THROW(TimeFunction({{0.0, 0.0}, {0.0, 1.0}}), std::invalid_argument);
}

// The tipping plate of thesis section 7.3: one edge hinged, the opposite edge lifted by a
// prescribed rotation history theta(t) about the hinge line (y axis), large rotations (total
// Lagrangian). Without load the exact answer is the rigid rotation of the whole plate: the
// lifted edge must follow X -> R(theta) X exactly and the free interior must follow it too.
TEST(LoadHistory, LiftedEdgeFollowsPrescribedRotationHistory) {
    ShellAnalysis analysis(make_plate(1.0, 0.5, 8, 4, 0.01), kSteel, Kinematics::total_lagrangian,
                           2);
    const ShellMesh& mesh = analysis.mesh();
    const double pi = std::numbers::pi;
    const TimeFunction tilt({{0.0, 0.0}, {0.5, 1.0}, {1.0, 0.5}});
    const double angle = pi / 4.0; // 45 deg at t = 0.5 s, back to 22.5 deg at 1 s
    analysis.prescribe(mesh.node_set("x0"), {0, 1, 2});
    analysis.use_history(analysis.add_history(tilt));
    analysis.prescribe_rigid_rotation(mesh.node_set("x1"), Vec3(0.0, -1.0, 0.0), Vec3::Zero(),
                                      angle);
    NewtonSettings settings;
    double worst_edge = 0.0, worst_interior = 0.0;
    for (const double t : {0.1, 0.25, 0.5, 0.75, 1.0}) {
        const StepReport report = analysis.advance_load(t, 2, settings);
        ASSERT_TRUE(report.converged) << "t = " << t;
        const Mat3 r = Eigen::AngleAxisd(tilt(t) * angle, Vec3(0.0, -1.0, 0.0)).toRotationMatrix();
        for (Index n = 0; n < mesh.node_count(); ++n) {
            const Vec3 exact = r * mesh.node(n) - mesh.node(n);
            const double error = (analysis.displacement(n) - exact).norm();
            const bool edge = mesh.node(n).x() > 1.0 - 1e-9;
            (edge ? worst_edge : worst_interior) =
                std::max(edge ? worst_edge : worst_interior, error);
        }
        const Index corner = mesh.nearest_node(Vec3(1.0, 0.5, 0.0));
        std::printf("t = %.2f s: theta = %6.3f deg, lifted edge z = %.9f m (exact %.9f)\n", t,
                    tilt(t) * angle * 180.0 / pi, analysis.displacement(corner).z(),
                    std::sin(tilt(t) * angle));
    }
    std::printf("largest error: lifted edge %.2e m, interior %.2e m\n", worst_edge, worst_interior);
    EXPECT_LT(worst_edge, 1e-12); // prescribed from the exact rotation: round-off
    // Rigid-body solution to the Newton tolerance (force ratio 1e-6): 2.3e-6 m on a 0.7 m lift.
    EXPECT_LT(worst_interior, 1e-5);
}

// A load with a piecewise-linear history on a linear elastic plate: the response at any time
// is the unit-load response scaled by the time function (superposition), including the
// unloading branch.
TEST(LoadHistory, PiecewiseLinearLoadScalesLinearResponse) {
    const auto build = [](ShellAnalysis& a) {
        const ShellMesh& mesh = a.mesh();
        for (const char* edge : {"x0", "x1", "y0", "y1"}) {
            a.prescribe(mesh.node_set(edge), {0, 1, 2});
        }
    };
    ShellAnalysis unit(make_plate(1.0, 1.0, 8, 8, 0.01), kSteel, Kinematics::linear, 2);
    build(unit);
    unit.add_pressure(-1e3);
    ASSERT_TRUE(unit.solve_linear().converged);
    const Index centre = unit.mesh().nearest_node(Vec3(0.5, 0.5, 0.0));
    const double w1 = unit.displacement(centre).z();

    ShellAnalysis history(make_plate(1.0, 1.0, 8, 8, 0.01), kSteel, Kinematics::linear, 2);
    build(history);
    const TimeFunction f({{0.0, 0.0}, {0.2, 0.5}, {0.6, 2.0}, {1.0, -1.0}});
    history.use_history(history.add_history(f));
    history.add_pressure(-1e3);
    history.use_history(0);
    for (const double t : {0.1, 0.2, 0.4, 0.6, 0.8, 1.0, 1.5}) {
        ASSERT_TRUE(history.advance_load(t, 1, NewtonSettings{}).converged);
        const double w = history.displacement(centre).z();
        std::printf("t = %.1f s: f = %+.3f, w = %+.6e m, f w1 = %+.6e m\n", t, f(t), w, f(t) * w1);
        EXPECT_NEAR(w, f(t) * w1, 1e-9 * std::abs(w1)) << "t = " << t;
    }
}

} // namespace
} // namespace grainload::fem
