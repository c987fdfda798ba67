#include "coupling/model_hints.hpp"
#include "fem/shell_analysis.hpp"
#include "fem/shell_mesh_generators.hpp"
#include "materials/linear_elastic.hpp"
#include "support/cantilever_strip.hpp"

#include <algorithm>
#include <gtest/gtest.h>

namespace grainload::coupling {
namespace {

// The run's largest shell stress is the structure's, not only the coupled elements': a
// cantilever strip (10 elements, nu = 0) under a tip force P has its largest moment, and face
// stress 6 M / t^2, in the root element (M = P (L - 0.05 m) at its centre), while the one
// element taken as coupled, at the tip, carries P x 0.05 m (a 19th of it). The extremes read
// the root's stress, to 1e-4 of Euler-Bernoulli's (measured 5e-6: the element's curvature
// from its nodal rotations, which the transverse shear flexibility moves slightly), and the
// coupled element's deflection.
TEST(ShellExtremes, StressIsTheWholeShellsDeflectionTheCoupledParts) {
    const materials::LinearElastic material(materials::ElasticConstants::from_young(1.0, 1e9, 0.0));
    fem::ShellAnalysis analysis(fem::make_plate(1.0, 0.1, 10, 1, 0.01), material,
                                fem::Kinematics::linear, 2);
    const fem::ShellMesh& mesh = analysis.mesh();
    const double force = 1.0;
    ASSERT_TRUE(testing::load_clamped_strip(analysis, 2, -force));
    // The element whose nodes lie at the tip, x = 1 m.
    Index tip = -1;
    for (std::size_t e = 0; e < mesh.elements().size(); ++e) {
        const auto& nodes = mesh.elements()[e].nodes;
        if (std::any_of(nodes.begin(), nodes.end(), [&](Index n) {
                return std::abs(mesh.nodes()[static_cast<std::size_t>(n)].x() - 1.0) < 1e-12;
            })) {
            tip = static_cast<Index>(e);
        }
    }
    ASSERT_GE(tip, 0);
    ShellExtremes extremes;
    extremes.add_deflection(analysis, {tip});
    extremes.add_stress(analysis);
    const double width = 0.1;
    const double thickness = 0.01;
    const double root = 6.0 * force * (1.0 - 0.05) / width / (thickness * thickness);
    EXPECT_NEAR(extremes.von_mises, root, 1e-4 * root);
    double tip_deflection = 0.0;
    for (const Index n : mesh.node_set("x1")) {
        tip_deflection = std::max(tip_deflection, analysis.displacement(n).norm());
    }
    EXPECT_EQ(extremes.deflection, tip_deflection);
}

} // namespace
} // namespace grainload::coupling
