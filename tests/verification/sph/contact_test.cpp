#include "sph_test_scene.hpp"

#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

using namespace testing;

/// Two elastic discs (plane strain) in an oblique frictionless collision through the contact
/// potential (thesis eq. 5.3.12): they must not interpenetrate, must separate, and the linear
/// momentum must be kept.
TEST(Contact, DiscsCollideSeparateAndDoNotInterpenetrate) {
    const auto& aluminium = elastic_material(70e9, 0.3, 2700.0);
    const double spacing = 0.002;
    const double radius = 0.02;
    ParticleSet particles;
    const Vec3 centres[2] = {Vec3(-0.023, -0.005, 0.0), Vec3(0.023, 0.005, 0.0)};
    const Vec3 velocities[2] = {Vec3(20.0, 0.0, 0.0), Vec3(-20.0, 0.0, 0.0)};
    for (int b = 0; b < 2; ++b) {
        ParticleSet square;
        LatticeBody body;
        body.spacing = spacing;
        body.density = aluminium.density();
        body.lower = centres[b] - Vec3(radius, radius, 0.0);
        body.upper = centres[b] + Vec3(radius, radius, 0.0);
        fill_box_lattice(square, body, 2);
        for (Index i = 0; i < square.size(); ++i) {
            if ((square.position[i] - centres[b]).norm() < radius) {
                particles.add(square.position[i], velocities[b], square.mass[i], square.density[i],
                              b, 0, 0);
            }
        }
    }
    SphOptions options = plane_strain_options(spacing);
    options.contact = {100.0 * 70e9, 1.0};
    options.viscosity = {0.5, 1.0};
    SphSolver solver(std::move(particles), {&aluminium}, options);
    const Vec3 p0 = solver.linear_momentum();
    const double c = aluminium.elastic().p_wave_speed();
    const double dt = solver.stable_time_step();
    double closest = smallest_neighbour_distance(solver, true);
    while (solver.time() < 0.012 / 20.0 + 8.0 * radius / c) {
        solver.step(dt);
        closest = std::min(closest, smallest_neighbour_distance(solver, true));
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
}

} // namespace
} // namespace grainload::sph
