#include "sph/rigid_wall.hpp"
#include "sph_test_scene.hpp"

#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

using namespace testing;

/// An elastic block (plane strain) hits a fixed plane wall of wall particles at 5 m/s: it must
/// rebound without passing the wall, and the impulse the wall takes (the time integral of its
/// recorded force) must equal the block's momentum change.
TEST(WallContact, BlockReboundsFromFixedWallAndWallImpulseMatchesMomentum) {
    const auto& aluminium = elastic_material(70e9, 0.3, 2700.0);
    const double spacing = 0.002;
    SphOptions options = plane_strain_options(spacing);
    options.contact = {100.0 * 70e9, 1.0};
    options.viscosity = {0.2, 0.4};
    ParticleSet particles;
    LatticeBody block;
    block.spacing = spacing;
    block.density = aluminium.density();
    // Face particles 2.7 dx from the first wall layer (at -dx/2): just outside 2h.
    const double gap = 1.7 * spacing;
    block.lower = Vec3(gap, 0.0, 0.0);
    block.upper = Vec3(gap + 0.04, 0.02, 0.0);
    block.velocity = Vec3(-5.0, 0.0, 0.0);
    fill_box_lattice(particles, block, 2);
    const auto points = plane_wall_points(Vec3(0.0, -0.01, 0.0), Vec3(0.0, 0.04, 0.0), Vec3::Zero(),
                                          Vec3(1.0, 0.0, 0.0), spacing, 3, 2);
    std::vector<Wall> walls;
    walls.push_back(add_wall(particles, "wall", 0, 1, points, spacing, 1.0, 2));
    SphSolver solver(std::move(particles), {&aluminium}, options, std::move(walls));
    const Vec3 p0 = solver.linear_momentum();
    const double c = aluminium.elastic().p_wave_speed();
    const double dt = solver.stable_time_step();
    Vec3 impulse = Vec3::Zero();
    double smallest_x = 1.0;
    while (solver.time() < 6.0 * 0.04 / c + 0.0003 / 5.0) {
        // Kick-drift-kick: the force at the end of a step acts for dt/2 on both sides of it.
        const Vec3 before = solver.walls()[0].force;
        solver.step(dt);
        impulse += 0.5 * dt * (before + solver.walls()[0].force);
        const auto& p = solver.particles();
        for (Index i = 0; i < p.size(); ++i) {
            if (!p.is_wall(i)) {
                smallest_x = std::min(smallest_x, p.position[i].x());
            }
        }
    }
    const Vec3 change = solver.linear_momentum() - p0;
    std::cout << "wall: momentum change " << change.x() << " N s/m, wall impulse " << -impulse.x()
              << ", closest particle " << smallest_x / spacing
              << " dx from the wall surface, final velocity "
              << solver.linear_momentum().x() / (2700.0 * 0.04 * 0.02) << " m/s\n";
    EXPECT_GT(solver.linear_momentum().x(), 0.0);
    EXPECT_GT(smallest_x, 0.5 * spacing);
    EXPECT_NEAR(-impulse.x(), change.x(), 1e-6 * std::abs(p0.x()));
}

} // namespace
} // namespace grainload::sph
