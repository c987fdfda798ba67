#include "materials/linear_elastic.hpp"
#include "sph/lattice_fill.hpp"
#include "sph/sph_solver.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <string>

namespace grainload::sph {
namespace {

const materials::LinearElastic& aluminium() {
    static const materials::LinearElastic material(
        materials::ElasticConstants::from_young(2700.0, 70e9, 0.3));
    return material;
}

SphSolver make_solver(int dimension, Vec3 gravity) {
    const auto elastic = aluminium().elastic();
    ParticleSet particles;
    LatticeBody body;
    body.upper = Vec3(0.05, 0.05, 0.05);
    body.spacing = 0.01;
    body.density = elastic.density;
    fill_box_lattice(particles, body, dimension);
    SphOptions options;
    options.dimension = dimension;
    options.kernel = KernelType::wendland_c2;
    options.kernel_gradient_correction = false;
    options.smoothing_length = 0.013;
    options.particle_spacing = 0.01;
    options.gravity = gravity;
    return SphSolver(std::move(particles), {&aluminium()}, options);
}

TEST(SphSolver, TimeStepAboveTheCflLimitIsRefusedWithTheLimit) {
    const SphSolver solver = make_solver(2, Vec3::Zero());
    const double c = materials::ElasticConstants::from_young(2700.0, 70e9, 0.3).p_wave_speed();
    const double limit = 0.3 * 0.013 / c;
    EXPECT_NEAR(solver.stable_time_step(), limit, 1e-12 * limit);
    EXPECT_NO_THROW(solver.check_time_step(0.99 * limit));
    try {
        solver.check_time_step(2.0 * limit);
        FAIL() << "expected the time step to be refused";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("CFL limit"), std::string::npos);
    }
}

TEST(SphSolver, UnstressedBodyFallsFreelyUnderGravity) {
    for (const int dimension : {2, 3}) {
        SphSolver solver = make_solver(dimension, Vec3(0.0, -9.81, 0.0));
        const double dt = solver.stable_time_step();
        for (int k = 0; k < 50; ++k) {
            solver.step(dt);
        }
        const double t = solver.time();
        for (Index i = 0; i < solver.particles().size(); ++i) {
            EXPECT_NEAR(solver.particles().velocity[i].y(), -9.81 * t, 1e-9);
        }
        const Vec3 p = solver.linear_momentum();
        EXPECT_NEAR(p.x(), 0.0, 1e-12);
    }
}

TEST(SphSolver, StiffnessScaleShortensTheCflLimitButKeepsTheViscositySoundSpeed) {
    // stiffness_scale s (materials/elastic_constants.hpp): K and G times s, so the P-wave speed
    // and the CFL step's 1/c change by sqrt(s); the artificial viscosity's c stays the unscaled
    // material's, so that alpha c (and with it the viscosity alpha c h) does not change.
    constexpr double kScale = 1e-3;
    const auto full = materials::ElasticConstants::from_young(2700.0, 70e9, 0.3);
    const materials::LinearElastic soft(full.scaled(kScale));
    EXPECT_DOUBLE_EQ(soft.elastic().bulk_modulus, kScale * full.bulk_modulus);
    EXPECT_DOUBLE_EQ(soft.elastic().shear_modulus, kScale * full.shear_modulus);
    ParticleSet particles;
    LatticeBody body;
    body.upper = Vec3(0.05, 0.05, 0.05);
    body.spacing = 0.01;
    body.density = full.density;
    fill_box_lattice(particles, body, 3);
    SphOptions options;
    options.smoothing_length = 0.013;
    options.particle_spacing = 0.01;
    options.viscosity = {1.0, 1.0};
    const SphSolver scaled(std::move(particles), {&soft}, options);
    const SphSolver reference = make_solver(3, Vec3::Zero());
    // Both at rest: dt = 0.3 h / c, and c scales with sqrt(s). Round-off only (a few ulp).
    constexpr double kRoundOff = 1e-12;
    EXPECT_NEAR(scaled.stable_time_step() * std::sqrt(kScale), reference.stable_time_step(),
                kRoundOff * reference.stable_time_step());
    for (const double c : scaled.force_inputs().sound_speed) {
        EXPECT_NEAR(c, full.p_wave_speed(), kRoundOff * full.p_wave_speed());
    }
    // The reference material (stiffness_scale 1) uses its own wave speed for both.
    for (const double c : reference.force_inputs().sound_speed) {
        EXPECT_EQ(c, full.p_wave_speed());
    }
}

// The density floor (SphSolver::integrate_density): a body flying apart, v = a (x - c), with
// a material too soft to resist (E = 1 Pa), loosens like a continuum, rho0 / (1 + a t)^3, while
// it is one; past half of rho0 no particle's density falls further. At a t = 1 the continuum
// density is rho0 / 8: without the floor the centre particle would read it, give or take the
// SPH divergence's error.
TEST(SphSolver, DensityOfABodyFlyingApartStopsAtHalfTheMaterialDensity) {
    static const materials::LinearElastic soft(
        materials::ElasticConstants::from_young(2700.0, 1.0, 0.3));
    ParticleSet particles;
    LatticeBody body;
    body.upper = Vec3(0.05, 0.05, 0.05);
    body.spacing = 0.01;
    body.density = 2700.0;
    fill_box_lattice(particles, body, 3);
    constexpr double kRate = 10.0; // a, 1/s
    const Vec3 centre(0.025, 0.025, 0.025);
    Index middle = 0;
    for (Index i = 0; i < particles.size(); ++i) {
        particles.velocity[i] = kRate * (particles.position[i] - centre);
        if ((particles.position[i] - centre).norm() <
            (particles.position[middle] - centre).norm()) {
            middle = i;
        }
    }
    SphOptions options;
    options.dimension = 3;
    options.kernel = KernelType::wendland_c2;
    options.kernel_gradient_correction = true; // exact for the linear velocity field
    options.smoothing_length = 0.013;
    options.particle_spacing = 0.01;
    SphSolver solver(std::move(particles), {&soft}, options);
    // While the centre is a continuum (a t = 0.1: rho0 / 1.331 = 0.75 rho0) it follows the
    // continuum: the corrected gradient is exact for the linear field v = a (x - c) / (1 + a t),
    // so only the explicit update of rho differs (first order in a dt = 2e-3; 1 %).
    constexpr double kStep = 2e-3 / kRate; // a dt = 2e-3: the explicit update's error is small
    for (int k = 0; k < 50; ++k) {
        solver.step(kStep);
    }
    const double loosened = 2700.0 / std::pow(1.0 + kRate * solver.time(), 3);
    EXPECT_NEAR(solver.particles().density[middle], loosened, 0.01 * loosened);
    for (int k = 50; k < 500; ++k) {
        solver.step(kStep);
    }
    for (Index i = 0; i < solver.particles().size(); ++i) {
        EXPECT_GE(solver.particles().density[i], 0.5 * 2700.0) << i;
    }
    EXPECT_DOUBLE_EQ(solver.particles().density[middle], 0.5 * 2700.0);
}

} // namespace
} // namespace grainload::sph
