#include "fem/shell_analysis.hpp"
#include "fem/shell_mesh_generators.hpp"
#include "materials/von_mises.hpp"

#include <cstdio>
#include <gtest/gtest.h>

namespace grainload::fem {
namespace {

// Elastic-perfectly-plastic strip bent by a prescribed end rotation (pure bending, free
// edges, so the stress is uniaxial): the moment follows M = Mp (1 - (k_y/k)^2 / 3) beyond
// first yield and tends to the limit moment Mp = sigma_y b t^2 / 4 (e.g. Lubliner,
// "Plasticity Theory", section 4.1.2). Steel-like: E = 200 GPa, nu = 0.3, sigma_y = 250 MPa;
// L = 1 m, b = 0.1 m, t = 0.1 m; 10 x 1 MITC4, 15 Gauss points through the thickness.
TEST(PlasticStrip, BendingMomentReachesLimitMoment) {
    const double young = 2e11, yield = 2.5e8, length = 1.0, width = 0.1, t = 0.1;
    const materials::VonMises steel(materials::ElasticConstants::from_young(7850, young, 0.3),
                                    yield, 0.0, 1.0);
    ShellAnalysis analysis(make_plate(length, width, 10, 1, t), steel, Kinematics::linear, 15);
    const ShellMesh& mesh = analysis.mesh();
    analysis.prescribe(mesh.node_set("x0"), {0, 1, 2, 3, 4, 5});
    const double kappa_y = 2.0 * yield / (young * t); // first-yield curvature
    const double kappa = 20.0 * kappa_y;
    analysis.prescribe(mesh.node_set("x1"), {4}, kappa * length);
    NewtonSettings settings;
    settings.force_tolerance = 1e-8;
    const StepReport report = analysis.advance_load(1.0, 20, settings);
    ASSERT_TRUE(report.converged);
    std::printf("increments %d, cut-backs %d, solver %s\n", report.increments, report.cutbacks,
                report.solver.c_str());
    std::size_t first = 0;
    for (std::size_t inc = 0; inc < report.iterations.size(); ++inc) {
        std::printf("increment %2zu:", inc + 1);
        for (int i = 0; i < report.iterations[inc]; ++i) {
            std::printf(" %.2e", report.log[first + static_cast<std::size_t>(i)].force_ratio);
        }
        std::printf("\n");
        first += static_cast<std::size_t>(report.iterations[inc]);
    }
    const Eigen::VectorXd reactions = analysis.reactions();
    double moment = 0.0;
    for (const Index n : mesh.node_set("x0")) {
        moment += reactions(6 * n + 4);
    }
    const double limit = yield * width * t * t / 4.0;
    const double expected = limit * (1.0 - 1.0 / (3.0 * 20.0 * 20.0));
    std::printf("root moment %.6g N m, analytic %.6g, limit moment %.6g (%.3f %% of Mp)\n",
                std::abs(moment), expected, limit, 100.0 * std::abs(moment) / limit);
    // 15-point Gauss integration of the elastic-plastic stress profile: error < 1 %; the
    // acceptance tolerance is 5 %.
    EXPECT_NEAR(std::abs(moment), expected, 0.01 * limit);
    // Every increment converges, and the plastic problem in few iterations thanks to the
    // consistent tangent of the return map condensed to plane stress.
    for (const int count : report.iterations) {
        EXPECT_LE(count, 8);
    }
}

} // namespace
} // namespace grainload::fem
