#include "sph/initial_stress.hpp"
#include "sph/lattice_fill.hpp"
#include "sph/rates.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

// A 2D column 10 x 20 particles (spacing 0.01 m, rho = 2000) under g = 9.81 down: the top is the
// highest particle centre plus dp/2 = 0.2 m, so a particle at height y carries
// sigma_yy = -rho g (0.2 - y), sigma_xx = sigma_zz = K0 sigma_yy, no shear (hand-computed).
TEST(InitialStress, GeostaticStressIsTheOverburdenWithK0Laterally) {
    ParticleSet p;
    LatticeBody column;
    column.upper = Vec3(0.1, 0.2, 0.0);
    column.spacing = 0.01;
    column.density = 2000.0;
    fill_box_lattice(p, column, 2);
    set_geostatic_stress(p, 0, Vec3(0.0, -9.81, 0.0), 0.01, 0.6);
    for (Index i = 0; i < p.size(); ++i) {
        const double vertical = -2000.0 * 9.81 * (0.2 - p.position[i].y());
        EXPECT_NEAR(p.stress[i][1], vertical, 1e-9);
        EXPECT_NEAR(p.stress[i][0], 0.6 * vertical, 1e-9);
        EXPECT_NEAR(p.stress[i][2], 0.6 * vertical, 1e-9);
        EXPECT_NEAR(p.stress[i].tail<3>().norm(), 0.0, 1e-9);
    }
}

// Gravity along a tilted direction: the stress is the same field in the rotated frame, so its
// principal values are sigma_v (along -g) and K0 sigma_v twice, and only particles from `first`
// on are touched.
TEST(InitialStress, GeostaticStressFollowsTheDirectionOfGravity) {
    ParticleSet p;
    LatticeBody block;
    block.upper = Vec3(0.05, 0.05, 0.05);
    block.spacing = 0.01;
    block.density = 1500.0;
    fill_box_lattice(p, block, 3);
    const Index first = 10;
    const Vec3 down = Vec3(1.0, -2.0, 0.5).normalized();
    set_geostatic_stress(p, first, 9.81 * down, 0.01, 0.4);
    double top = -1e9;
    for (Index i = first; i < p.size(); ++i) {
        top = std::max(top, -p.position[i].dot(down) + 0.005);
    }
    for (Index i = 0; i < p.size(); ++i) {
        if (i < first) {
            EXPECT_EQ(p.stress[i].norm(), 0.0);
            continue;
        }
        const double vertical = -1500.0 * 9.81 * (top + p.position[i].dot(down));
        const Mat3 sigma = stress_tensor(p.stress[i]);
        EXPECT_NEAR(down.dot(sigma * down), vertical, 1e-9);
        EXPECT_LT((sigma * down - vertical * down).norm(), 1e-9);
        EXPECT_NEAR(sigma.trace(), vertical * (1.0 + 2.0 * 0.4), 1e-9);
    }
}

} // namespace
} // namespace grainload::sph
