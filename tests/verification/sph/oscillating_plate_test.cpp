#include "sph_test_scene.hpp"

#include <chrono>
#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

using namespace testing;

// The oscillating elastic plate of Gray, Monaghan & Swift (2001): a plane-strain cantilever
// plate, L = 0.2 m long and H = 0.02 m thick (rho = 1000 kg/m^3, E = 2 MPa, nu = 0.3975),
// built into a clamped root and started with the transverse velocity of its first mode. The
// same set-up, frequency formula and mode shape are used by the SPHinXsys 2D oscillating beam.
//
// Reference: thin-plate theory in cylindrical bending. In plane strain the plate cannot contract
// across its width, so its bending stiffness per unit width is D = E H^3 / (12 (1 - nu^2)): the
// plane-strain modulus E / (1 - nu^2), not E, enters, and the first-mode frequency is
//   omega^2 = D k^4 / (rho H) = E H^2 k^4 / (12 rho (1 - nu^2)),  1 + cos(kL) cosh(kL) = 0,
// kL = 1.8751, T = 2 pi / omega = 0.2540 s. With E alone (a beam) T would be 9 % longer.
//
// Two formulations are checked (docs/validation/oscillating_plate.md):
//
// Updated Lagrangian (the sand's formulation): a plate too soft in bending at every resolution
// that fits CI, for two measured reasons: (1) the corrected gradient is exact for linear fields
// only, and at the one-sided free surfaces the outer row reads the strain of a fibre 0.32
// spacings further in, so the bending stiffness is 0.897 of D with 8 particles across H
// (kinematic check; 0.648 with 4); (2) the built-in root is compliant: the first free columns
// rotate as if the plate were clamped 1.4 spacings inside the clamped block, 0.93 of the
// stiffness at 8 particles. With Timoshenko's 0.986 the expected stiffness is 0.82, a period
// 10.4 % above thin-plate theory; measured +10.7 %. Above 8 particles across H the tensile
// instability sets in without artificial stress (+22 % at 12) and GMS's artificial stress costs
// 3-7 % of the stiffness, so this formulation does not converge to theory here. Asserted: the
// 8-particle period within [0, +12 %] (the +10.4 % budget and 1.5 % for its own uncertainty: a
// plate that used E instead of E / (1 - nu^2) would be 9 % softer still and fail), 8 particles
// closer to theory than 6, a clamped root that never moves.
//
// Total Lagrangian (sph/total_lagrangian.hpp): the same two first-order deficits, but no tensile
// instability, so the spacing can be refined without artificial stress and the period
// converges: +9.65 / +5.08 / +3.37 % at 8 / 12 / 16 particles across H (measured). Asserted: the
// 16-particle period within [0, +5 %] of thin-plate theory, the acceptance criterion (the period of
// the thick plate, H/L = 0.1, lies 0.7 % above thin-plate theory, so 0 is a hard lower bound),
// 16 particles closer than 12, no pairing (closest pair above 0.95 spacings: an instability
// would pair particles, as it does in the updated-Lagrangian plate at 12), a root that never
// moves.
//
// Clamp off (no particle flagged; tried): the initial momentum, all upward, carries the whole
// plate away, the tip rises 55 mm within 2 T_ref and never comes back through zero, the periods
// are NaN and the test fails.

constexpr double kLength = 0.2;
constexpr double kThickness = 0.02;
constexpr double kDensity = 1000.0;
constexpr double kYoung = 2.0e6;
constexpr double kPoisson = 0.3975;
constexpr double kModeRoot = 1.8751040687; // first root of 1 + cos(kL) cosh(kL) = 0

/// First cantilever mode, zero with zero slope at x = 0, normalised to 1 at x = L.
double mode_shape(double x) {
    const double k = kModeRoot / kLength;
    auto f = [k](double s) {
        const double kl = kModeRoot;
        return (std::cos(kl) + std::cosh(kl)) * (std::cosh(k * s) - std::cos(k * s)) +
               (std::sin(kl) - std::sinh(kl)) * (std::sinh(k * s) - std::sin(k * s));
    };
    return f(x) / f(kLength);
}

struct PlateRun {
    double period = std::nan(""); ///< s: the tip's first return through zero going up
    double root_motion = 0.0;     ///< largest displacement of a clamped particle, m
    double tip_amplitude = 0.0;   ///< largest tip deflection, m
    double closest_pair = 1.0;    ///< smallest particle distance seen, in spacings
    double wall_seconds = 0.0;
};

/// Plate of `rows` particles across H plus a clamped root of 4 spacings (more than the 2h
/// support, so the first free particles see a full neighbourhood of fixed ones). The tip
/// displacement is the mean y-displacement of the last column; it starts at zero moving up,
/// so its first upward zero crossing after it has been below zero is one full period. The run
/// stops there, or at twice the reference period (no crossing: NaN).
PlateRun run_plate(int rows, double tip_velocity, double reference_period,
                   Formulation formulation) {
    const auto& rubber = elastic_material(kYoung, kPoisson, kDensity);
    const double spacing = kThickness / rows;
    ParticleSet particles;
    LatticeBody plate;
    plate.spacing = spacing;
    plate.density = kDensity;
    plate.lower = Vec3(-4.0 * spacing, 0.0, 0.0);
    plate.upper = Vec3(kLength, kThickness, 0.0);
    fill_box_lattice(particles, plate, 2);
    for (Index i = 0; i < particles.size(); ++i) {
        const double x = particles.position[i].x();
        particles.clamped[i] = x < 0.0 ? 1 : 0;
        particles.velocity[i].y() = x < 0.0 ? 0.0 : tip_velocity * mode_shape(x);
    }
    SphOptions options = plane_strain_options(spacing);
    options.kernel_gradient_correction = true;
    // Without viscosity the particle noise of the clamped root grows until particles pair up
    // near the neutral axis (t = 0.09 s); alpha = 0.1 keeps them ordered and damps the first
    // mode little (tip amplitude 5.37 mm at 8 particles against 5.53 mm undamped, H/4 scaled by
    // the longer period). No artificial stress: its pair term does not vanish with resolution,
    // and with GMS's epsilon = 0.3 the 8-particle plate was 3 % softer (T 0.2859 s, not 0.2812).
    // Over one period of alternating tension the particles stay ordered without it (closest
    // pair 0.92 spacings at 8 particles); the gravity-loaded case, in tension for good, needs it.
    // The total-Lagrangian plate needs neither: its pairs are fixed (closest pair 0.99 spacings
    // with alpha = 0 at 12 particles, period unchanged from alpha = 0.1 to 1e-5 relative).
    options.viscosity = {formulation == Formulation::updated_lagrangian ? 0.1 : 0.0, 0.0};
    options.formulation = formulation;
    const std::vector<Vec3> start = particles.position;
    SphSolver solver(std::move(particles), {&rubber}, options);
    const auto& p = solver.particles();
    auto at_tip = [&](Index i) { return start[i].x() > kLength - spacing; };
    auto tip_displacement = [&] {
        return mean_over(p, at_tip, [&](Index i) { return p.position[i].y() - start[i].y(); });
    };

    PlateRun run;
    const double dt = solver.stable_time_step();
    const auto began = std::chrono::steady_clock::now();
    bool went_below = false;
    double previous = 0.0;
    while (solver.time() < 2.0 * reference_period) {
        solver.step(dt);
        const double tip = tip_displacement();
        run.tip_amplitude = std::max(run.tip_amplitude, std::abs(tip));
        if (solver.step_count() % 20 == 0) {
            run.closest_pair =
                std::min(run.closest_pair, smallest_neighbour_distance(solver, false));
        }
        if (went_below && previous < 0.0 && tip >= 0.0) {
            run.period = solver.time() - dt * tip / (tip - previous);
            break;
        }
        went_below = went_below || tip < 0.0;
        previous = tip;
    }
    run.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    for (Index i = 0; i < p.size(); ++i) {
        if (p.clamped[i]) {
            run.root_motion = std::max(run.root_motion, (p.position[i] - start[i]).norm());
        }
    }
    return run;
}

double thin_plate_period() {
    const double k = kModeRoot / kLength;
    const double omega = std::sqrt(kYoung * kThickness * kThickness * std::pow(k, 4) /
                                   (12.0 * kDensity * (1.0 - kPoisson * kPoisson)));
    return 2.0 * std::numbers::pi / omega;
}

/// Tip amplitude H/4 = 2.5 % of L (thin-plate theory): small enough for linear theory (the
/// large-amplitude frequency shift goes as (amplitude / L)^2), far above the noise.
double tip_velocity() {
    return 2.0 * std::numbers::pi / thin_plate_period() * 0.25 * kThickness;
}

void report(const char* label, int rows, const PlateRun& run, double reference) {
    std::cout << "oscillating plate, " << label << ", " << rows << " particles across H: period "
              << run.period << " s (" << 100.0 * (run.period / reference - 1.0)
              << " %), tip amplitude " << run.tip_amplitude << " m, closest pair "
              << run.closest_pair << " spacings, clamped particles moved at most "
              << run.root_motion << " m, " << run.wall_seconds << " s\n";
}

TEST(OscillatingPlate, UpdatedLagrangianPeriodIsThinPlateTheoryLessTheKnownSphDeficits) {
    const double reference = thin_plate_period();
    const auto ul = Formulation::updated_lagrangian;
    const PlateRun coarse = run_plate(6, tip_velocity(), reference, ul);
    const PlateRun fine = run_plate(8, tip_velocity(), reference, ul);
    report("updated Lagrangian", 6, coarse, reference);
    report("updated Lagrangian", 8, fine, reference);
    EXPECT_GT(fine.period / reference, 1.0);
    EXPECT_LT(fine.period / reference, 1.12);
    EXPECT_LT(std::abs(fine.period / reference - 1.0), std::abs(coarse.period / reference - 1.0));
    EXPECT_EQ(coarse.root_motion, 0.0);
    EXPECT_EQ(fine.root_motion, 0.0);
}

TEST(OscillatingPlate, TotalLagrangianPeriodConvergesToWithinFivePercentOfThinPlateTheory) {
    const double reference = thin_plate_period();
    const auto tl = Formulation::total_lagrangian;
    const PlateRun coarse = run_plate(12, tip_velocity(), reference, tl);
    const PlateRun fine = run_plate(16, tip_velocity(), reference, tl);
    report("total Lagrangian", 12, coarse, reference);
    report("total Lagrangian", 16, fine, reference);
    RecordProperty("period_16_rows", std::to_string(fine.period));
    EXPECT_GT(fine.period / reference, 1.0);
    EXPECT_LT(fine.period / reference, 1.05);
    EXPECT_LT(fine.period, coarse.period);
    EXPECT_GT(fine.closest_pair, 0.95);
    EXPECT_EQ(coarse.root_motion, 0.0);
    EXPECT_EQ(fine.root_motion, 0.0);
}

} // namespace
} // namespace grainload::sph
