#include "fem/shell_analysis.hpp"
#include "fem/shell_mesh_generators.hpp"
#include "materials/linear_elastic.hpp"

#include <cstdio>
#include <gtest/gtest.h>
#include <numbers>

namespace grainload::fem {
namespace {

// Cantilever strip under an end moment M = 2 pi E I / L rolls into a full circle (the
// classical large-rotation test; e.g. Sze, Liu & Lo 2004, Finite Elem. Anal. Des. 40:1551):
// L = 12, b = 1, t = 0.1, E = 1.2e6, nu = 0, 32 x 1 MITC4 elements, total Lagrangian.
// Measured tip distance from the root: 16 elements 2.8 % of L, 32 elements 0.74 %, 64 0.25 %.
TEST(CantileverRollUp, EndMomentRollsIntoFullCircle) {
    const double length = 12.0;
    const double thickness = 0.1;
    const double young = 1.2e6;
    const materials::LinearElastic material(
        materials::ElasticConstants::from_young(1.0, young, 0.0));
    ShellAnalysis analysis(make_plate(length, 1.0, 32, 1, thickness), material,
                           Kinematics::total_lagrangian, 2);
    const ShellMesh& mesh = analysis.mesh();
    analysis.prescribe(mesh.node_set("x0"), {0, 1, 2, 3, 4, 5});
    const double inertia = 1.0 * thickness * thickness * thickness / 12.0;
    const double moment = 2.0 * std::numbers::pi * young * inertia / length;
    for (const Index n : mesh.node_set("x1")) {
        analysis.add_nodal_load(n, 4, -0.5 * moment); // about -y: the strip curls up (+z)
    }
    NewtonSettings settings;
    settings.force_tolerance = 1e-8;
    settings.energy_tolerance = 1e-14;
    const StepReport report = analysis.advance_load(1.0, 40, settings);
    std::printf("increments %d, cut-backs %d, solver %s\n", report.increments, report.cutbacks,
                report.solver.c_str());
    std::printf(" it  |dU|/|U|       |R|/|R0|       energy ratio\n");
    for (const auto& it : report.log) {
        std::printf("%3d  %.3e      %.3e      %.3e\n", it.iteration, it.displacement_ratio,
                    it.force_ratio, it.energy_ratio);
    }
    ASSERT_TRUE(report.converged);
    EXPECT_EQ(report.cutbacks, 0);
    for (const Index n : mesh.node_set("x1")) {
        const Vec3 tip = mesh.node(n) + analysis.displacement(n);
        std::printf("tip node %lld at (%.5f, %.5f, %.5f)\n", static_cast<long long>(n), tip.x(),
                    tip.y(), tip.z());
        // Acceptance criterion: back at the root within 1 % of L.
        EXPECT_LT(std::hypot(tip.x(), tip.z()), 0.01 * length);
    }
    // Quadratic convergence: the last contraction of each increment before round-off
    // (force ratio still above 1e-6) must be at least quadratic, |R(i)| <= 10 |R(i-1)|^2 in
    // the ratios of eq. 5.2.8.
    std::size_t first = 0;
    for (const int count : report.iterations) {
        const std::size_t end = first + static_cast<std::size_t>(count);
        std::size_t last_pair = 0;
        for (std::size_t i = first + 1; i < end; ++i) {
            if (report.log[i - 1].force_ratio > 1e-6) {
                last_pair = i;
            }
        }
        ASSERT_GT(last_pair, first);
        const double previous = report.log[last_pair - 1].force_ratio;
        EXPECT_LT(report.log[last_pair].force_ratio, 10.0 * previous * previous);
        first = end;
    }
}

} // namespace
} // namespace grainload::fem
