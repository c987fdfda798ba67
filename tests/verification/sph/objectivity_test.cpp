#include "sph/stress_update.hpp"
#include "sph_test_scene.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

using namespace testing;

Vec3 principal(const Voigt6& stress) {
    Eigen::SelfAdjointEigenSolver<Mat3> eigen;
    eigen.computeDirect(stress_tensor(stress));
    return eigen.eigenvalues();
}

/// A pre-stressed body in rigid rotation (quarter turn in 100 steps, prescribed motion) goes
/// through the SPH kinematics and the Jaumann stress update (thesis eq. 4.6.1.8): its
/// principal stresses must stay put to 1e-6 and the stress must turn with the body.
TEST(Objectivity, RigidlyRotatingStressedBodyKeepsItsPrincipalStresses) {
    const auto& aluminium = elastic_material(70e9, 0.3, 2700.0);
    for (const int dimension : {2, 3}) {
        const double spacing = 0.01;
        ParticleSet particles;
        LatticeBody block;
        block.spacing = spacing;
        block.density = aluminium.density();
        block.lower = Vec3(-0.05, -0.05, -0.05);
        block.upper = Vec3(0.05, 0.05, 0.05);
        fill_box_lattice(particles, block, dimension);
        Voigt6 initial;
        initial << 100e6, -50e6, 20e6, 30e6, dimension == 3 ? 10e6 : 0.0,
            dimension == 3 ? -15e6 : 0.0;
        const Vec3 omega =
            dimension == 2 ? Vec3(0.0, 0.0, 50.0) : Vec3(1.0, 2.0, 3.0).normalized() * 50.0;
        for (Index i = 0; i < particles.size(); ++i) {
            particles.stress[i] = initial;
            particles.velocity[i] = omega.cross(particles.position[i]);
        }
        const SmoothingKernel kernel(KernelType::cubic_spline, 1.3 * spacing, dimension);
        particles::NeighbourList neighbours(kernel.support_radius(), 0.0, dimension);
        const std::vector<const materials::Material*> materials{&aluminium};
        const int steps = 100;
        const double dt = 0.5 * std::numbers::pi / omega.norm() / steps;
        const Mat3 step_rotation =
            Eigen::AngleAxisd(omega.norm() * dt, omega.normalized()).matrix();
        std::vector<Mat3> gradient;
        std::vector<Mat3> correction;
        for (int k = 0; k < steps; ++k) {
            for (Index i = 0; i < particles.size(); ++i) {
                // Exact rotation of the positions; the rigid velocity field at the new ones.
                particles.position[i] = step_rotation * particles.position[i];
                particles.velocity[i] = omega.cross(particles.position[i]);
            }
            neighbours.update(particles.position, {});
            compute_velocity_gradient(particles, neighbours, kernel, true, gradient, correction);
            update_stresses(particles, materials, dt);
        }
        const Vec3 expected_principal = principal(initial);
        const Mat3 turn = Eigen::AngleAxisd(0.5 * std::numbers::pi, omega.normalized()).matrix();
        const Mat3 expected = turn * stress_tensor(initial) * turn.transpose();
        double worst_principal = 0.0;
        double worst_tensor = 0.0;
        for (Index i = 0; i < particles.size(); ++i) {
            worst_principal = std::max(
                worst_principal, (principal(particles.stress[i]) - expected_principal).norm());
            worst_tensor =
                std::max(worst_tensor, (stress_tensor(particles.stress[i]) - expected).norm());
        }
        const double scale = expected_principal.norm();
        std::cout << dimension << "D rigid rotation: principal stresses to "
                  << worst_principal / scale << ", stress tensor to " << worst_tensor / scale
                  << " (relative)\n";
        EXPECT_LT(worst_principal, 1e-6 * scale);
        EXPECT_LT(worst_tensor, 1e-3 * scale);
    }
}

} // namespace
} // namespace grainload::sph
