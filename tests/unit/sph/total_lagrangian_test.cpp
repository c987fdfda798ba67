#include "sph/lattice_fill.hpp"
#include "sph/rates.hpp"
#include "sph/total_lagrangian.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <gtest/gtest.h>
#include <random>

namespace grainload::sph {
namespace {

constexpr double kDensity = 1000.0;

ParticleSet lattice_block(int dimension, int per_side) {
    ParticleSet particles;
    LatticeBody body;
    body.upper = Vec3::Constant(per_side * 0.1);
    body.spacing = 0.1;
    body.density = kDensity;
    fill_box_lattice(particles, body, dimension);
    return particles;
}

Mat3 plane(Mat3 a, int dimension) {
    if (dimension == 2) {
        a.row(2).setZero();
        a.col(2).setZero();
    }
    return a;
}

// F = grad0 x and L = grad v are exact for affine motions at every particle, corners and
// surfaces included: the reference gradient is corrected (first-order consistent) and a
// lattice corner keeps M's smallest singular value above the blend threshold (rates.hpp). A
// 40 degree rotation with stretch makes any spurious stress of an uncorrected F show.
TEST(TotalLagrangian, DeformationGradientAndVelocityGradientAreExactForAffineMotions) {
    for (const int dimension : {2, 3}) {
        ParticleSet p = lattice_block(dimension, 6);
        const SmoothingKernel kernel(KernelType::cubic_spline, 0.13, dimension);
        TotalLagrangian total(p, kernel);
        const Mat3 rotation = Eigen::AngleAxisd(0.7, Vec3(0.0, 0.0, 1.0)).toRotationMatrix();
        Mat3 stretch;
        stretch << 1.1, 0.05, 0.02, 0.0, 0.93, -0.04, 0.0, 0.0, 1.07;
        const Mat3 f = dimension == 2
                           ? Mat3(rotation * (plane(stretch, 2) + Mat3(Vec3(0, 0, 1).asDiagonal())))
                           : Mat3(rotation * stretch);
        Mat3 b;
        b << 0.3, -1.2, 0.4, 0.7, -0.5, 0.1, 0.2, 0.9, 0.25;
        b = plane(b, dimension);
        for (Index i = 0; i < p.size(); ++i) {
            p.position[i] = f * p.position[i] + Vec3(0.3, -0.2, dimension == 3 ? 0.1 : 0.0);
            p.velocity[i] = b * p.position[i];
        }
        std::vector<Mat3> velocity_gradient;
        total.compute_kinematics(p, velocity_gradient);
        for (Index i = 0; i < p.size(); ++i) {
            EXPECT_LT((total.deformation_gradient()[i] - f).norm(), 1e-12) << "particle " << i;
            EXPECT_LT((velocity_gradient[i] - b).norm(), 1e-10) << "particle " << i;
            EXPECT_NEAR(p.density[i], kDensity / f.determinant(), 1e-9);
        }
    }
}

// Work consistency of kinematics and forces: for any positions, velocities and stresses the
// power of the stress forces, sum_i m_i a_i . v_i, equals -sum_i V0_i P_i : dF_i/dt =
// -sum_i V0_i J_i sigma_i : L_i (swap i and j in the pair sum), which is what the stress update
// books as internal energy. A wrong sign, transpose or volume in either pass breaks it. The
// forces also sum to zero (pair terms antisymmetric).
TEST(TotalLagrangian, StressForcePowerEqualsMinusTheStressPowerAndForcesSumToZero) {
    for (const int dimension : {2, 3}) {
        ParticleSet p = lattice_block(dimension, 5);
        const SmoothingKernel kernel(KernelType::cubic_spline, 0.13, dimension);
        TotalLagrangian total(p, kernel);
        std::mt19937 random(7);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        auto jitter = [&] {
            return Vec3(unit(random), unit(random), dimension == 3 ? unit(random) : 0.0);
        };
        for (Index i = 0; i < p.size(); ++i) {
            p.position[i] += 0.02 * jitter();
            p.velocity[i] = jitter();
            for (int k = 0; k < 6; ++k) {
                p.stress[i][k] = 1e3 * unit(random);
            }
        }
        std::vector<Mat3> velocity_gradient;
        total.compute_kinematics(p, velocity_gradient);
        for (Index i = 0; i < p.size(); ++i) {
            p.acceleration[i].setZero();
        }
        total.add_stress_forces(p);
        double force_power = 0.0;
        double stress_power = 0.0;
        double scale = 0.0;
        Vec3 force_sum = Vec3::Zero();
        for (Index i = 0; i < p.size(); ++i) {
            const Vec3 force = p.mass[i] * p.acceleration[i];
            force_power += force.dot(p.velocity[i]);
            force_sum += force;
            scale += force.norm() * p.velocity[i].norm();
            const double volume0 = p.mass[i] / kDensity;
            const double jacobian = total.deformation_gradient()[i].determinant();
            stress_power += volume0 * jacobian *
                            (stress_tensor(p.stress[i]).cwiseProduct(velocity_gradient[i])).sum();
        }
        EXPECT_NEAR(force_power, -stress_power, 1e-12 * scale) << "dimension " << dimension;
        EXPECT_LT(force_sum.norm(), 1e-12 * scale);
    }
}

} // namespace
} // namespace grainload::sph
