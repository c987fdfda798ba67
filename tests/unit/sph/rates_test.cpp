#include "sph/lattice_fill.hpp"
#include "sph/rates.hpp"
#include "sph/stress_update.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <gtest/gtest.h>
#include <random>

namespace grainload::sph {
namespace {

struct Block {
    ParticleSet particles;
    SmoothingKernel kernel;
    particles::NeighbourList neighbours;
};

Block make_block(int dimension, int per_side, KernelType type = KernelType::cubic_spline) {
    const double spacing = 0.1;
    ParticleSet particles;
    LatticeBody body;
    body.upper = Vec3::Constant(per_side * spacing);
    body.spacing = spacing;
    body.density = 1000.0;
    fill_box_lattice(particles, body, dimension);
    SmoothingKernel kernel(type, 1.3 * spacing, dimension);
    particles::NeighbourList neighbours(kernel.support_radius(), 0.0, dimension);
    neighbours.update(particles.position, {});
    return {std::move(particles), kernel, std::move(neighbours)};
}

Mat3 plane(Mat3 a, int dimension) {
    if (dimension == 2) {
        a.row(2).setZero();
        a.col(2).setZero();
    }
    return a;
}

TEST(Rates, CorrectedVelocityGradientIsExactForLinearFields) {
    for (const int dimension : {2, 3}) {
        Block b = make_block(dimension, 6);
        Mat3 a;
        a << 0.3, -1.2, 0.4, 0.7, -0.5, 0.1, 0.2, 0.9, 0.25;
        a = plane(a, dimension);
        for (Index i = 0; i < b.particles.size(); ++i) {
            b.particles.velocity[i] = a * b.particles.position[i];
        }
        std::vector<Mat3> gradient;
        std::vector<Mat3> correction;
        compute_velocity_gradient(b.particles, b.neighbours, b.kernel, true, gradient, correction);
        ASSERT_EQ(correction.size(), static_cast<std::size_t>(b.particles.size()));
        for (Index i = 0; i < b.particles.size(); ++i) {
            EXPECT_LT((gradient[i] - a).norm(), 1e-10) << "particle " << i;
            EXPECT_NEAR(b.particles.density_rate[i], -1000.0 * a.trace(), 1e-7);
        }
        // Engineering shear and axial spin vector of the plain gradient.
        const Index i = 0;
        EXPECT_NEAR(b.particles.strain_rate[i][3], a(0, 1) + a(1, 0), 1e-10);
        EXPECT_NEAR(b.particles.spin[i].z(), 0.5 * (a(1, 0) - a(0, 1)), 1e-10);
    }
}

TEST(Rates, PlainVelocityGradientIsAccurateInTheInterior) {
    Block b = make_block(2, 12, KernelType::cubic_spline);
    Mat3 a = Mat3::Zero();
    a(0, 0) = 1.0;
    a(0, 1) = 0.5;
    for (Index i = 0; i < b.particles.size(); ++i) {
        b.particles.velocity[i] = a * b.particles.position[i];
    }
    std::vector<Mat3> gradient;
    std::vector<Mat3> correction;
    compute_velocity_gradient(b.particles, b.neighbours, b.kernel, false, gradient, correction);
    EXPECT_TRUE(correction.empty());
    const Vec3 centre(0.55, 0.55, 0.0);
    for (Index i = 0; i < b.particles.size(); ++i) {
        if ((b.particles.position[i] - centre).norm() < 0.2) {
            EXPECT_LT((gradient[i] - a).norm(), 2e-2 * a.norm());
        }
    }
}

TEST(Rates, InternalForcesSumToZeroForceAndWithCorrectionZeroTorque) {
    for (const bool corrected : {false, true}) {
        for (const int dimension : {2, 3}) {
            Block b = make_block(dimension, 5);
            std::mt19937 generator(1u);
            std::uniform_real_distribution<double> value(-1e6, 1e6);
            for (Index i = 0; i < b.particles.size(); ++i) {
                for (int c = 0; c < 6; ++c) {
                    b.particles.stress[i][c] = value(generator);
                }
                if (dimension == 2) { // plane strain: no out-of-plane shear
                    b.particles.stress[i][4] = 0.0;
                    b.particles.stress[i][5] = 0.0;
                }
                b.particles.velocity[i] = Vec3(value(generator), value(generator), 0.0) * 1e-6;
            }
            SphOptions options;
            options.dimension = dimension;
            options.particle_spacing = 0.1;
            options.viscosity = {1.0, 2.0};
            // Artificial stress is not torque-free; it is checked for the force sum only.
            options.artificial_stress = {corrected ? 0.0 : 0.3, 4.0};
            ForceInputs inputs;
            inputs.sound_speed.assign(static_cast<std::size_t>(b.particles.size()), 100.0);
            std::vector<Mat3> gradient;
            compute_velocity_gradient(b.particles, b.neighbours, b.kernel, corrected, gradient,
                                      inputs.gradient_correction);
            prepare_force_inputs(b.particles, options.artificial_stress, inputs);
            std::vector<double> heating;
            compute_accelerations(b.particles, b.neighbours, b.kernel, options, inputs, heating);
            Vec3 total = Vec3::Zero();
            Vec3 torque = Vec3::Zero();
            double scale = 0.0;
            double torque_scale = 0.0;
            for (Index i = 0; i < b.particles.size(); ++i) {
                const Vec3 f = b.particles.mass[i] * b.particles.acceleration[i];
                total += f;
                torque += b.particles.position[i].cross(f);
                scale += f.norm();
                torque_scale += b.particles.position[i].norm() * f.norm();
            }
            EXPECT_LT(total.norm(), 1e-12 * scale) << dimension << "D";
            if (corrected) {
                EXPECT_LT(torque.norm(), 1e-12 * torque_scale) << dimension << "D";
            }
        }
    }
}

TEST(Rates, ContactPotentialIsRepulsiveAndPairwise) {
    ParticleSet p;
    p.add(Vec3(0, 0, 0), Vec3::Zero(), 10.0, 1000.0, 0, 0, 0);
    p.add(Vec3(0.08, 0.02, 0), Vec3::Zero(), 10.0, 1000.0, 1, 0, 0);
    SmoothingKernel kernel(KernelType::wendland_c2, 0.12, 2);
    particles::NeighbourList list(kernel.support_radius(), 0.0, 2);
    list.update(p.position, {});
    SphOptions options;
    options.dimension = 2;
    options.particle_spacing = 0.1;
    options.contact = {1e6, 2.0};
    ForceInputs inputs;
    inputs.sound_speed.assign(2, 0.0);
    prepare_force_inputs(p, options.artificial_stress, inputs);
    std::vector<double> heating;
    compute_accelerations(p, list, kernel, options, inputs, heating);
    const Vec3 separation = p.position[0] - p.position[1];
    EXPECT_GT(p.acceleration[0].dot(separation), 0.0);
    EXPECT_LT((p.acceleration[0] + p.acceleration[1]).norm(), 1e-12 * p.acceleration[0].norm());
    EXPECT_LT(p.acceleration[0].cross(separation).norm(), 1e-12 * p.acceleration[0].norm());
}

TEST(Rates, JaumannRotationIsOrthogonalAndSecondOrder) {
    const Vec3 spin(0.3, -0.2, 1.1);
    const double dt = 1e-3;
    const Mat3 q = jaumann_rotation(spin, dt);
    EXPECT_LT((q * q.transpose() - Mat3::Identity()).norm(), 1e-15);
    Mat3 w;
    w << 0.0, -spin.z(), spin.y(), spin.z(), 0.0, -spin.x(), -spin.y(), spin.x(), 0.0;
    Mat3 sigma;
    sigma << 3, 1, 0.5, 1, -2, 0.2, 0.5, 0.2, 1;
    const Mat3 rotated = q * sigma * q.transpose();
    const Mat3 jaumann = sigma + dt * (w * sigma - sigma * w);
    EXPECT_LT((rotated - jaumann).norm(), 10.0 * dt * dt * sigma.norm());
}

// The closed form against the Cayley transform as Hughes & Winget define it, (I - dt/2 W)^-1
// (I + dt/2 W) with the inverse taken by Eigen, from a small spin to one that turns by more
// than a radian in the step: the two differ by round-off of the inverse (a few ulps of 1).
TEST(Rates, JaumannRotationIsTheCayleyTransform) {
    for (const double dt : {1e-6, 1e-3, 1.0, 3.0}) {
        const Vec3 spin(0.3, -0.2, 1.1);
        Mat3 w;
        w << 0.0, -spin.z(), spin.y(), spin.z(), 0.0, -spin.x(), -spin.y(), spin.x(), 0.0;
        const Mat3 half = 0.5 * dt * w;
        const Mat3 cayley = (Mat3::Identity() - half).inverse() * (Mat3::Identity() + half);
        EXPECT_LT((jaumann_rotation(spin, dt) - cayley).norm(), 1e-15) << "dt = " << dt;
    }
}

// A flow front thinned to one row with one neighbour a little off the line: M (the
// Randles-Libersky moment) has det well above 1e-3 but a smallest singular value near 0.01, so
// the full correction would multiply a neighbour's velocity noise by ~100 and the continuity
// equation could make the density negative in one step. The correction must fall back to the
// plain gradient there, while lattice corners (smallest singular value >= 0.21) stay exact
// (CorrectedVelocityGradientIsExactForLinearFields).
TEST(Rates, GradientCorrectionFallsBackAtNearlyCollinearNeighbours) {
    const double spacing = 0.1;
    const double offset = 0.02; // the off-line neighbour's distance from the row, m
    ParticleSet p;
    for (int k = -2; k <= 2; ++k) {
        const double y = k == 1 ? offset : 0.0;
        p.add(Vec3(k * spacing, y, 0.0), Vec3::Zero(), 1000.0 * spacing * spacing, 1000.0, 0, 0, 0);
    }
    const Index centre = 2;
    p.velocity[3] = Vec3(0.0, 1e-3, 0.0); // velocity noise on the off-line neighbour
    const SmoothingKernel kernel(KernelType::cubic_spline, 1.3 * spacing, 2);
    particles::NeighbourList neighbours(kernel.support_radius(), 0.0, 2);
    neighbours.update(p.position, {});

    // The moment as the solver forms it, to show the configuration is the dangerous one.
    Mat3 moment = Mat3::Zero();
    for (Index j = 0; j < p.size(); ++j) {
        const Vec3 x_ij = p.position[centre] - p.position[j];
        if (j != centre && x_ij.norm() < kernel.support_radius()) {
            moment += (-p.mass[j] / p.density[centre] * x_ij) *
                      kernel.gradient(x_ij, x_ij.norm()).transpose();
        }
    }
    const Eigen::Matrix2d in_plane = moment.topLeftCorner<2, 2>();
    const Eigen::JacobiSVD<Eigen::Matrix2d> svd(in_plane);
    ASSERT_GT(in_plane.determinant(), 1e-3);
    ASSERT_LT(svd.singularValues()(1), 0.05);

    std::vector<Mat3> plain;
    std::vector<Mat3> corrected;
    std::vector<Mat3> correction;
    compute_velocity_gradient(p, neighbours, kernel, false, plain, correction);
    compute_velocity_gradient(p, neighbours, kernel, true, corrected, correction);
    EXPECT_LT((correction[centre] - Mat3::Identity()).norm(), 1e-14);
    EXPECT_LT((corrected[centre] - plain[centre]).norm(), 1e-12 * plain[centre].norm());
    // What the inverse would have done: amplify the same noise by 1/s.
    Mat3 padded = moment; // plane strain: zz = 1, as the solver does
    padded(2, 2) = 1.0;
    const Mat3 full = plain[centre] * padded.inverse();
    EXPECT_GT(full.norm(), 20.0 * plain[centre].norm());
}

// [sph.artificial_viscosity] sound_speed pins the c of Monaghan's linear term: a block whose
// moduli were scaled by 1/100 (c / 10) must feel the same viscous forces as the unscaled one
// when the unscaled c is given, and ten times smaller linear-term forces without it.
TEST(Rates, ViscositySoundSpeedReplacesTheMaterialsWaveSpeed) {
    Block b = make_block(2, 5);
    std::mt19937 generator(3u);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    for (Index i = 0; i < b.particles.size(); ++i) {
        b.particles.velocity[i] = Vec3(value(generator), value(generator), 0.0);
    }
    const auto accelerations = [&](double material_speed, double pinned_speed) {
        SphOptions options;
        options.dimension = 2;
        options.particle_spacing = 0.1;
        options.viscosity = {1.0, 0.0, pinned_speed};
        ForceInputs inputs;
        inputs.sound_speed.assign(static_cast<std::size_t>(b.particles.size()), material_speed);
        prepare_force_inputs(b.particles, options.artificial_stress, inputs);
        std::vector<double> heating;
        compute_accelerations(b.particles, b.neighbours, b.kernel, options, inputs, heating);
        return b.particles.acceleration;
    };
    const auto stiff = accelerations(100.0, 0.0);
    const auto pinned = accelerations(10.0, 100.0);
    const auto soft = accelerations(10.0, 0.0);
    double viscous = 0.0;
    for (Index i = 0; i < b.particles.size(); ++i) {
        EXPECT_EQ(stiff[i], pinned[i]) << "particle " << i;
        EXPECT_LT((soft[i] - stiff[i] / 10.0).norm(), 1e-12 * stiff[i].norm() + 1e-15);
        viscous += stiff[i].norm();
    }
    EXPECT_GT(viscous, 0.0);
}

} // namespace
} // namespace grainload::sph
