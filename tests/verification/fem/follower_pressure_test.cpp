#include "fem/shell_analysis.hpp"
#include "fem/shell_mesh_generators.hpp"
#include "materials/linear_elastic.hpp"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <numbers>

namespace grainload::fem {
namespace {

// A thin cylinder (R = 1 m, t = 10 mm, steel, free ends) under external follower pressure,
// quarter model by symmetry, large displacements (total Lagrangian). The membrane solution
// of a ring is a uniform radial displacement u = p R^2 / (E t) inwards (hoop stress p R / t).
// The follower load stiffness makes the tangent non-symmetric: UMFPACK must run, and Newton
// must keep converging quadratically.
TEST(FollowerPressure, CylinderUnderExternalPressureMatchesMembraneSolution) {
    const double radius = 1.0, t = 0.01, young = 2.1e11, nu = 0.3;
    const materials::LinearElastic steel(materials::ElasticConstants::from_young(7850, young, nu));
    for (const double p : {1e3, 1e4}) { // 1.7 % and 17 % of the ring's buckling pressure
        ShellAnalysis analysis(make_cylinder(radius, 0.25, 0.0, 0.5 * std::numbers::pi, 8, 2, t),
                               steel, Kinematics::total_lagrangian, 2);
        const ShellMesh& mesh = analysis.mesh();
        analysis.prescribe(mesh.node_set("phi0"), {0, 4, 5}); // symmetry plane x = 0
        analysis.prescribe(mesh.node_set("phi1"), {2, 3, 4}); // symmetry plane z = 0
        analysis.prescribe(mesh.node_set("y0"), {1, 3, 5});   // symmetry plane y = 0
        analysis.add_follower_pressure(-p);                   // generator normals point outwards
        const StepReport report = analysis.advance_load(1.0, 2, NewtonSettings{});
        ASSERT_TRUE(report.converged);
        EXPECT_EQ(report.solver, "UMFPACK LU");
        double mean = 0.0;
        for (Index n = 0; n < mesh.node_count(); ++n) {
            const Vec3 x = mesh.node(n);
            const Vec3 radial(x.x(), 0.0, x.z());
            mean -= analysis.displacement(n).dot(radial.normalized()) / double(mesh.node_count());
        }
        const double membrane = p * radius * radius / (young * t);
        std::printf("p = %.0f Pa: radial displacement %.6e m, membrane p R^2/(E t) = %.6e m "
                    "(%+.3f %%); iterations per increment %d, %d; residual norms",
                    p, mean, membrane, 100.0 * (mean / membrane - 1.0), report.iterations[0],
                    report.iterations[1]);
        for (const auto& it : report.log) {
            std::printf(" %.2e", it.residual_norm);
        }
        std::printf("\n");
        if (p == 1e3) {
            EXPECT_NEAR(mean, membrane, 0.01 * membrane);
        }
        for (const int iterations : report.iterations) {
            EXPECT_LE(iterations, 4); // quadratic: no more than a handful per increment
        }
    }
}

} // namespace
} // namespace grainload::fem
