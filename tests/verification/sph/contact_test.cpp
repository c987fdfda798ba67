#include "sph/contact_force.hpp"
#include "sph_test_scene.hpp"

#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

using namespace testing;

constexpr double kSpacing = 0.002;
constexpr double kRadius = 0.02;

/// Two aluminium discs (plane strain) 6 mm apart moving at each other at 20 m/s, obliquely
/// (centres 10 mm apart across the line of approach), with contact stiffness 100 E and no
/// contact damping.
SphSolver make_discs() {
    const auto& aluminium = elastic_material(70e9, 0.3, 2700.0);
    ParticleSet particles;
    const Vec3 centres[2] = {Vec3(-0.023, -0.005, 0.0), Vec3(0.023, 0.005, 0.0)};
    const Vec3 velocities[2] = {Vec3(20.0, 0.0, 0.0), Vec3(-20.0, 0.0, 0.0)};
    for (int b = 0; b < 2; ++b) {
        ParticleSet square;
        LatticeBody body;
        body.spacing = kSpacing;
        body.density = aluminium.density();
        body.lower = centres[b] - Vec3(kRadius, kRadius, 0.0);
        body.upper = centres[b] + Vec3(kRadius, kRadius, 0.0);
        fill_box_lattice(square, body, 2);
        for (Index i = 0; i < square.size(); ++i) {
            if ((square.position[i] - centres[b]).norm() < kRadius) {
                particles.add(square.position[i], velocities[b], square.mass[i], square.density[i],
                              b, 0, 0);
            }
        }
    }
    SphOptions options = plane_strain_options(kSpacing);
    options.contact = {100.0 * 70e9, 1.0};
    options.viscosity = {0.5, 1.0};
    return SphSolver(std::move(particles), {&aluminium}, options);
}

/// The discs in an oblique frictionless collision through the contact potential (thesis
/// eq. 5.3.12): they must not interpenetrate, must separate, and the linear momentum must be
/// kept.
///
/// With no contact damping the potential is conservative: kinetic plus internal energy (stress
/// power and viscous heat) plus the energy stored in the potential, U = K V_i V_j W(dp)
/// (W/W(dp))^n / n, must stay at the initial kinetic energy through the collision. U peaks at
/// several per cent of it, so a wrong closed form for U (or a contact force that is not its
/// gradient) shows up as a balance error of that order; leapfrog's O(dt^2) error and the
/// volumes' change with density (U holds them fixed) stay far below.
TEST(Contact, DiscsCollideSeparateAndDoNotInterpenetrate) {
    SphSolver solver = make_discs();
    const auto& aluminium = *solver.materials()[0];
    const double radius = kRadius;
    const Vec3 p0 = solver.linear_momentum();
    const double c = aluminium.elastic().p_wave_speed();
    const double dt = solver.stable_time_step();
    double closest = smallest_neighbour_distance(solver, true);
    const double initial = solver.kinetic_energy();
    double largest_stored = 0.0;
    double largest_error = 0.0;
    while (solver.time() < 0.012 / 20.0 + 8.0 * radius / c) {
        solver.step(dt);
        closest = std::min(closest, smallest_neighbour_distance(solver, true));
        const double stored = solver.contact_energy();
        largest_stored = std::max(largest_stored, stored);
        const double held = solver.held_energy() + stored;
        largest_error = std::max(largest_error, std::abs(held - initial) / initial);
    }
    const auto& p = solver.particles();
    const double v_left = mean_over(
        p, [&](Index i) { return p.body_id[i] == 0; }, [&](Index i) { return p.velocity[i].x(); });
    const double v_right = mean_over(
        p, [&](Index i) { return p.body_id[i] == 1; }, [&](Index i) { return p.velocity[i].x(); });
    std::cout << "discs: closest approach " << closest << " spacings, separating velocities "
              << v_left << " / " << v_right << " m/s\n";
    EXPECT_GT(closest, 1.0);
    EXPECT_LT(v_left, 0.0);
    EXPECT_GT(v_right, 0.0);
    EXPECT_LT((solver.linear_momentum() - p0).norm(), 1e-12 * solver.kinetic_energy());
    std::cout << "discs: largest contact energy " << largest_stored / initial
              << " of the initial kinetic energy, largest balance error " << largest_error << "\n";
    EXPECT_GT(largest_stored, 0.02 * initial);
    EXPECT_LT(largest_error, 0.1 * largest_stored / initial);
}

// U(r) is the work of the repulsion from r out to the support's edge: compare it with a
// composite Simpson quadrature of contact_repulsion (error ~1e-10 at 2000 intervals).
TEST(Contact, ContactEnergyIsTheWorkOfTheRepulsion) {
    const SmoothingKernel kernel(KernelType::cubic_spline, 1.3 * kSpacing, 2);
    const double w_reference = kernel.value(kSpacing);
    const double volumes = kSpacing * kSpacing * kSpacing * kSpacing;
    const double edge = kernel.support_radius();
    for (const double exponent : {1.0, 2.0, 3.5}) {
        const ContactPotential contact{1e9, exponent};
        for (const double r : {0.8 * kSpacing, 1.5 * kSpacing, 2.4 * kSpacing}) {
            const int intervals = 2000;
            const double step = (edge - r) / intervals;
            double integral = 0.0;
            for (int k = 0; k <= intervals; ++k) {
                const double weight = (k == 0 || k == intervals) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
                integral +=
                    weight * contact_repulsion(kernel, contact, w_reference, volumes, r + k * step);
            }
            integral *= step / 3.0;
            const double closed = contact_energy(kernel, contact, w_reference, volumes, r);
            EXPECT_NEAR(closed, integral, 1e-8 * integral) << "n = " << exponent << ", r = " << r;
        }
    }
}

} // namespace
} // namespace grainload::sph
