#include "sph_test_scene.hpp"

#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

using namespace testing;

// Plane-strain P wave: the two halves of a block (1 m x 0.4 m) move towards each other at
// +-v0; compression fronts run out of the mid-plane at c_p = sqrt((K + 4G/3)/rho), the speed
// the CFL condition uses. With nu = 0.3 it is 16 % above the bar speed sqrt(E/rho), so the
// 2 % tolerance tells the two apart. The speed is taken from the arrival times of the
// half-plateau stress at two stations on the centre line, which cancels the start-up.
TEST(WaveSpeed, PlaneStrainPWaveSpeedWithinTwoPercent) {
    const double spacing = 0.01;
    const auto& steel = elastic_material(200e9, 0.3, 7850.0);
    const double c_p = steel.elastic().p_wave_speed();
    const double v0 = 1.0;
    ParticleSet particles;
    LatticeBody body;
    body.upper = Vec3(1.0, 0.4, 0.0);
    body.spacing = spacing;
    body.density = steel.density();
    fill_box_lattice(particles, body, 2);
    for (Index i = 0; i < particles.size(); ++i) {
        particles.velocity[i].x() = particles.position[i].x() < 0.5 ? v0 : -v0;
    }
    SphSolver solver(std::move(particles), {&steel}, plane_strain_options(spacing));
    const double stations[2] = {0.605, 0.855};
    std::vector<double> times;
    std::vector<double> stress[2];
    const double dt = solver.stable_time_step();
    while (solver.time() < 0.42 / c_p) {
        solver.step(dt);
        times.push_back(solver.time());
        for (int s = 0; s < 2; ++s) {
            const auto& p = solver.particles();
            stress[s].push_back(mean_over(
                p,
                [&](Index i) {
                    return std::abs(p.position[i].x() - stations[s]) < 0.5 * spacing &&
                           std::abs(p.position[i].y() - 0.2) < 0.05;
                },
                [&](Index i) { return p.stress[i][0]; }));
        }
    }
    const double plateau = -steel.density() * c_p * v0;
    const double arrival_near = first_crossing_down(times, stress[0], 0.5 * plateau);
    const double arrival_far = first_crossing_down(times, stress[1], 0.5 * plateau);
    const double measured = (stations[1] - stations[0]) / (arrival_far - arrival_near);
    RecordProperty("measured_speed", std::to_string(measured));
    std::cout << "P-wave speed: measured " << measured << " m/s, analytic " << c_p << " m/s, error "
              << 100.0 * (measured / c_p - 1.0) << " %\n";
    EXPECT_NEAR(measured / c_p, 1.0, 0.02);
}

} // namespace
} // namespace grainload::sph
