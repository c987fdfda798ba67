#include "fem/shell_analysis.hpp"
#include "materials/linear_elastic.hpp"

#include <functional>
#include <gtest/gtest.h>

namespace grainload::fem {
namespace {

// MacNeal & Harder (1985) patch: 0.24 x 0.12 rectangle, five distorted elements, t = 0.001,
// E = 1e6, nu = 0.25. Boundary (corner) nodes follow an exact constant-strain / constant-
// curvature field; the interior nodes and the element stresses must reproduce it to round-off.
constexpr double kThickness = 0.001;
const materials::LinearElastic kMaterial(materials::ElasticConstants::from_young(1.0, 1e6, 0.25));

ShellMesh distorted_patch() {
    ShellMesh mesh;
    for (const auto& [x, y] : {std::pair{0.0, 0.0},
                               {0.24, 0.0},
                               {0.24, 0.12},
                               {0.0, 0.12},
                               {0.04, 0.02},
                               {0.18, 0.03},
                               {0.16, 0.08},
                               {0.08, 0.08}}) {
        mesh.add_node(Vec3(x, y, 0.0));
    }
    for (const auto& e : {std::array<Index, 4>{0, 1, 5, 4},
                          {1, 2, 6, 5},
                          {2, 3, 7, 6},
                          {3, 0, 4, 7},
                          {4, 5, 6, 7}}) {
        mesh.add_element(e, kThickness);
    }
    return mesh;
}

using Field = std::function<Eigen::Matrix<double, 6, 1>(const Vec3&)>;

void run_patch(const Field& exact, const std::function<void(const ShellResultants&)>& check) {
    ShellAnalysis analysis(distorted_patch(), kMaterial, Kinematics::linear, 2);
    for (Index n = 0; n < 4; ++n) {
        const auto value = exact(analysis.mesh().node(n));
        for (int d = 0; d < 6; ++d) {
            analysis.prescribe(n, d, value(d));
        }
    }
    ASSERT_TRUE(analysis.solve_linear().converged);
    // Round-off here is machine epsilon times the condition number of the thin patch
    // (~(L/t)^2 = 1e4..1e5), hence relative tolerances of 1e-10 below.
    for (Index n = 4; n < 8; ++n) {
        const auto value = exact(analysis.mesh().node(n));
        for (int d = 0; d < 5; ++d) { // the drilling rotation carries no stiffness of its own
            const double got = d < 3 ? analysis.displacement(n)(d) : analysis.rotation(n)(d - 3);
            EXPECT_NEAR(got, value(d), 1e-10 * value.cwiseAbs().maxCoeff())
                << "node " << n << " dof " << d;
        }
    }
    for (const auto& element : analysis.elements()) {
        check(element.resultants());
    }
}

TEST(PatchTest, MembraneDistortedToRoundOff) {
    // u = 1e-3 (x + y/2), v = 1e-3 (y + x/2): eps_x = eps_y = gamma_xy = 1e-3.
    const auto exact = [](const Vec3& x) {
        Eigen::Matrix<double, 6, 1> v = Eigen::Matrix<double, 6, 1>::Zero();
        v(0) = 1e-3 * (x.x() + x.y() / 2.0);
        v(1) = 1e-3 * (x.y() + x.x() / 2.0);
        return v;
    };
    const double c = 1e6 / (1.0 - 0.25 * 0.25);
    const double n_normal = c * (1e-3 + 0.25e-3) * kThickness; // N_xx = N_yy
    const double n_shear = 1e6 / 2.5 * 1e-3 * kThickness;      // N_xy = G gamma t
    run_patch(exact, [&](const ShellResultants& r) {
        // The element frame's axis 1 follows its own edge r, so compare invariants.
        EXPECT_NEAR(r.membrane(0) + r.membrane(1), 2.0 * n_normal, 1e-10 * n_normal);
        const double radius = std::hypot(0.5 * (r.membrane(0) - r.membrane(1)), r.membrane(2));
        EXPECT_NEAR(radius, n_shear, 1e-10 * n_normal);
        EXPECT_NEAR(r.bending.norm(), 0.0, 1e-12 * n_normal * kThickness);
    });
}

TEST(PatchTest, BendingDistortedToRoundOff) {
    // w = 1e-3 (x^2 + xy + y^2)/2 with Kirchhoff rotations theta_x = dw/dy,
    // theta_y = -dw/dx: constant curvatures, zero transverse shear.
    const auto exact = [](const Vec3& x) {
        Eigen::Matrix<double, 6, 1> v = Eigen::Matrix<double, 6, 1>::Zero();
        v(2) = 1e-3 * (x.x() * x.x() + x.x() * x.y() + x.y() * x.y()) / 2.0;
        v(3) = 1e-3 * (x.y() + x.x() / 2.0);
        v(4) = -1e-3 * (x.x() + x.y() / 2.0);
        return v;
    };
    const double d = 1e6 * std::pow(kThickness, 3) / (12.0 * (1.0 - 0.25 * 0.25));
    const double m_normal = d * (1e-3 + 0.25e-3); // |M_xx| = |M_yy|
    const double m_twist = d * (1.0 - 0.25) / 2.0 * 1e-3;
    run_patch(exact, [&](const ShellResultants& r) {
        EXPECT_NEAR(std::abs(r.bending(0) + r.bending(1)), 2.0 * m_normal, 1e-10 * m_normal);
        const double radius = std::hypot(0.5 * (r.bending(0) - r.bending(1)), r.bending(2));
        EXPECT_NEAR(radius, m_twist, 1e-10 * m_normal);
        EXPECT_NEAR(r.membrane.norm(), 0.0, 1e-10 * m_normal / kThickness);
    });
}

} // namespace
} // namespace grainload::fem
