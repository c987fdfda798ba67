#include "sph/rigid_wall.hpp"
#include "sph_test_scene.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

using namespace testing;

// A thin elastic block (plane strain, 30 x 5 particles) on a rigid floor y = 0 with Coulomb
// friction mu_s = 0.5 (onset at atan 0.5 = 26.57 deg), mu_k = 0.4. Tilting the plate by theta
// is the same as tilting gravity: g = 9.81 (sin theta, -cos theta). Coulomb's law for a block:
//   at rest for tan theta <= mu_s, else sliding at a = g (sin theta - mu_k cos theta).
constexpr double kSpacing = 0.002;
constexpr double kGravity = 9.81;
constexpr double kMuStatic = 0.5;
constexpr double kMuKinetic = 0.4;

Vec3 tilted_gravity(double theta) {
    return kGravity * Vec3(std::sin(theta), -std::cos(theta), 0.0);
}

struct FrictionScene {
    std::unique_ptr<SphSolver> solver;
    double mass = 0.0;
};

/// Block of 30 x 5 particles whose base particles touch the floor's wall particles at the edge
/// of the support (2h = 2.6 dp), so it starts with no contact force.
FrictionScene make_scene(double theta, const Vec3& floor_velocity, double mu_kinetic = kMuKinetic) {
    const auto& soil = elastic_material(5e6, 0.3, 2000.0);
    ParticleSet particles;
    LatticeBody body;
    body.spacing = kSpacing;
    body.density = soil.density();
    // Wall particles at half the body spacing: a wall sampled at dp sums the kernel's tail at
    // 0.77 h steps and is corrugated enough that the normal dashpot, damping the bobbing of
    // a particle sliding over it, adds a spurious drag (measured: -25 % on the sliding
    // acceleration at dp, +0.3 % at dp/2).
    const double ws = 0.5 * kSpacing;
    const double base = 2.1 * kSpacing - 0.5 * ws;
    body.lower = Vec3(0.0, base, 0.0);
    body.upper = Vec3(30 * kSpacing, base + 5.0 * kSpacing, 0.0);
    fill_box_lattice(particles, body, 2);
    FrictionScene scene;
    for (Index i = 0; i < particles.size(); ++i) {
        scene.mass += particles.mass[i];
    }
    const int layers = static_cast<int>(std::ceil(2.6 * kSpacing / ws));
    const auto floor_points = plane_wall_points(Vec3(-0.2, 0.0, 0.0), Vec3(0.5, 0.0, 0.0),
                                                Vec3::Zero(), Vec3(0.0, 1.0, 0.0), ws, layers, 2);
    Wall floor = add_wall(particles, "floor", 0, 1, floor_points, ws, 1.0, 2);
    attach_rigid_motion(particles, floor, floor_velocity, Vec3::Zero());
    floor.normals.assign(floor_points.size(), Vec3(0.0, 1.0, 0.0));
    SphOptions options = plane_strain_options(kSpacing);
    options.gravity = tilted_gravity(theta);
    options.contact = {5e6, 1.0, 0.5};
    options.viscosity = {0.5, 0.5};
    options.friction = {FrictionPair{0, 1, kMuStatic, mu_kinetic}};
    scene.solver = std::make_unique<SphSolver>(std::move(particles), SphSolver::MaterialList{&soil},
                                               options, [&] {
                                                   std::vector<Wall> walls;
                                                   walls.push_back(std::move(floor));
                                                   return walls;
                                               }());
    return scene;
}

Vec3 block_mean(const SphSolver& solver, bool velocity) {
    const auto& p = solver.particles();
    Vec3 sum = Vec3::Zero();
    int count = 0;
    for (Index i = 0; i < p.size(); ++i) {
        if (!p.is_wall(i)) {
            sum += velocity ? p.velocity[i] : p.position[i];
            ++count;
        }
    }
    return sum / count;
}

void run_until(SphSolver& solver, double end) {
    const double dt = solver.stable_time_step();
    while (solver.time() < end - 0.5 * dt) {
        solver.step(dt);
    }
}

double degrees(double d) {
    return d * std::numbers::pi / 180.0;
}

TEST(WallFriction, BlockSticksBelowTheFrictionAngleAndSlidesAboveIt) {
    const double onset = std::atan(kMuStatic);
    double slide_below = 0.0;
    double slide_above = 0.0;
    // mu_k = mu_s here. With mu_k < mu_s an elastic block starts sliding below atan(mu_s):
    // the overturning moment unloads its uphill edge (normal traction -24 % at H/L = 1/6),
    // that edge slips first, drops to mu_k and sheds load onto the rest, which then slips in
    // turn (measured: 2 dp slid at onset - 1 deg with mu_k = 0.4). That is the physics of
    // slip weakening, not an error; the rigid-block answer assumes uniform traction.
    for (const double theta : {onset - degrees(1.0), onset + degrees(1.0)}) {
        // Settle on the level plate (the contact layer's bounce is damped in ~25 ms), then
        // tilt it slowly, as in the experiment: over 50 ms, far longer than the block's
        // shear-wave transit (~1 ms), so the load is quasi-static.
        FrictionScene scene = make_scene(0.0, Vec3::Zero(), kMuStatic);
        SphSolver& solver = *scene.solver;
        run_until(solver, 0.03);
        const Vec3 start = block_mean(solver, false);
        while (solver.time() < 0.08) {
            solver.set_gravity(tilted_gravity(theta * (solver.time() - 0.03) / 0.05));
            solver.step(solver.stable_time_step());
        }
        solver.set_gravity(tilted_gravity(theta));
        run_until(solver, 0.18);
        const double slid = (block_mean(solver, false) - start).x();
        (theta < onset ? slide_below : slide_above) = slid;
    }
    // Sliding from onset + 1 deg (reached at 0.077 s) to 0.18 s with mu_k = mu_s: a = 0.19
    // m/s^2 gives ~1 mm (0.5 dp). Held at onset - 1 deg the block only deforms elastically:
    // tau ~ rho g H sin(theta) = 90 Pa gives a shear displacement ~1e-6 m (5e-4 dp).
    std::cout << "slid from 0.03 to 0.18 s: " << slide_below / kSpacing << " dp at onset - 1 deg, "
              << slide_above / kSpacing << " dp at onset + 1 deg\n";
    EXPECT_LT(std::abs(slide_below), 0.05 * kSpacing);
    EXPECT_GT(slide_above, 0.25 * kSpacing);
}

TEST(WallFriction, SlidingAccelerationIsGTimesSinMinusMuKineticCos) {
    const double theta = degrees(35.0);
    FrictionScene scene = make_scene(theta, Vec3::Zero());
    run_until(*scene.solver, 0.05);
    const double t0 = scene.solver->time();
    const double v0 = block_mean(*scene.solver, true).x();
    run_until(*scene.solver, 0.15);
    const double a = (block_mean(*scene.solver, true).x() - v0) / (scene.solver->time() - t0);
    const double exact = kGravity * (std::sin(theta) - kMuKinetic * std::cos(theta));
    std::cout << "sliding acceleration " << a << " m/s^2, g (sin - mu_k cos) = " << exact
              << ", relative error " << (a - exact) / exact << "\n";
    // The acceptance tolerance (5 %); the base particles' normal load fluctuates with the contact
    // layer's oscillation, which averages out over the 0.1 s window.
    EXPECT_NEAR(a, exact, 0.05 * exact);
}

TEST(WallFriction, ConveyorBeltAcceleratesTheBlockAtMuKineticGUntilItSticks) {
    const double belt = 0.2;
    FrictionScene scene = make_scene(0.0, Vec3(belt, 0.0, 0.0));
    SphSolver& solver = *scene.solver;
    // Kinetic friction mu_k m g accelerates the block until it moves with the belt at
    // t = belt / (mu_k g) = 51 ms; then static friction holds it there.
    const double catch_up = belt / (kMuKinetic * kGravity);
    run_until(solver, 0.5 * catch_up);
    const double v_half = block_mean(solver, true).x();
    run_until(solver, 2.0 * catch_up);
    const double v_end = block_mean(solver, true).x();
    std::cout << "belt: block speed " << v_half << " m/s at t_c/2 (exact " << 0.5 * belt << "), "
              << v_end << " m/s at 2 t_c (belt " << belt << ")\n";
    // The block settles onto the belt in the first ~5 ms (contact first loaded at t = 0), so
    // the friction force builds up with a short lag: 5 % of the half-way speed.
    EXPECT_NEAR(v_half, 0.5 * belt, 0.05 * 0.5 * belt);
    EXPECT_NEAR(v_end, belt, 1e-3 * belt);
    // The belt carries the block's weight and, once stuck, no tangential force.
    const Wall& floor = solver.walls()[0];
    EXPECT_NEAR(floor.force.y(), -scene.mass * kGravity, 0.02 * scene.mass * kGravity);
    EXPECT_LT(std::abs(floor.force.x()), 0.02 * scene.mass * kGravity);
}

// The belt's energy books (EnergyLedger): while the block slips, the belt's friction force
// mu_k m g acts over the belt's own travel v_b t_c, so the belt does W = mu_k m g v_b t_c = m
// v_b^2, half of it kinetic energy of the block (m v_b^2 / 2) and half heat of friction (the slip
// distance v_b t_c / 2 times mu_k m g). Once stuck, the belt does no more work.
TEST(WallFriction, ConveyorBeltWorkIsHalfKineticEnergyHalfFrictionHeat) {
    const double belt = 0.2;
    FrictionScene scene = make_scene(0.0, Vec3(belt, 0.0, 0.0));
    SphSolver& solver = *scene.solver;
    run_until(solver, 2.0 * belt / (kMuKinetic * kGravity));
    const EnergyLedger& ledger = solver.energy_ledger();
    const double expected = scene.mass * belt * belt;
    const double balance = ledger.balance_error(solver.held_energy(), solver.contact_energy());
    std::cout << "belt work " << ledger.wall_work() / expected << " m v^2, friction heat "
              << solver.wall_contact().friction_work() / expected << " m v^2, kinetic energy "
              << solver.kinetic_energy() / expected << " m v^2, balance " << balance
              << " of the throughput\n";
    // 1 %: the wall work's first-order time quadrature (reaction at the step's end times the
    // wall's velocity) over the ~700 steps of the slip phase. The friction heat is short of
    // m v^2 / 2 by what the normal dashpot dissipates while the block settles and bobs on the
    // moving lattice (0.3 % measured, booked as heat but not as friction work): 2 %.
    EXPECT_NEAR(ledger.wall_work(), expected, 0.01 * expected);
    EXPECT_NEAR(solver.wall_contact().friction_work(), 0.5 * expected, 0.02 * expected);
    EXPECT_NEAR(solver.kinetic_energy(), 0.5 * expected, 0.01 * expected);
    // What the books leave out is leapfrog's error and the wall work's first-order time
    // quadrature (reaction at the step's end times the wall's velocity): 1 %.
    EXPECT_LT(std::abs(balance), 0.01);
}

} // namespace
} // namespace grainload::sph
