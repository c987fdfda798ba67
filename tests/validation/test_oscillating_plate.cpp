#include "support/case_runner.hpp"
#include "support/plate_tip.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <vector>

namespace {

using namespace grainload::testing;

// cases/oscillating_plate/oscillating_plate.toml: Gray, Monaghan & Swift's cantilever plate,
// total Lagrangian, 16 particles across H, released under g = 1 m/s^2 (docs/validation/
// oscillating_plate.md, "Case (CLI): sudden gravity"). About 3.5 min on 2 threads.
constexpr double kSpacing = 0.00125;
constexpr double kInterval = 0.002; // output_interval of the case

/// The swing's figures as cases/oscillating_plate/analyse.py takes them: the level is the
/// midpoint of the extremes, refined (three times) to the time average over the whole periods
/// between the first and the last downward crossing of it; the period is that span over the
/// number of periods.
struct Swing {
    double level = 0.0;
    double period = 0.0;
    std::size_t periods = 0;
};

Swing measure_swing(const std::vector<double>& tip) {
    const auto [low, high] = std::minmax_element(tip.begin(), tip.end());
    Swing swing;
    swing.level = 0.5 * (*low + *high);
    for (int pass = 0; pass < 3; ++pass) {
        const auto down = crossings_down(tip, swing.level, kInterval);
        if (down.size() < 2) {
            return {};
        }
        const auto first = static_cast<std::size_t>(std::ceil(down.front() / kInterval));
        const auto last = static_cast<std::size_t>(std::floor(down.back() / kInterval));
        double integral = 0.0;
        for (std::size_t k = first; k < last; ++k) {
            integral += 0.5 * (tip[k] + tip[k + 1]) * kInterval;
        }
        swing.level = integral / (static_cast<double>(last - first) * kInterval);
    }
    const auto down = crossings_down(tip, swing.level, kInterval);
    if (down.size() < 2) {
        return {};
    }
    swing.periods = down.size() - 1;
    swing.period = (down.back() - down.front()) / static_cast<double>(swing.periods);
    return swing;
}

// Reference, thin-plate theory in cylindrical bending (plane strain): first-mode period
// T = 0.2540 s, static tip deflection q L^4 / (8 D) = 2.526 mm, the level the tip swings about.
// - Period within [0, +5 %] of T, the criterion the page validates against (measured +3.33 %
//   over 3 periods). 0 is a hard bound: the thick plate's own period (H/L = 0.1, shear and
//   rotary inertia) is 0.7 % above thin-plate theory, and SPH's first-order deficits (one-sided
//   surface rows, compliant root) only soften the plate further.
// - Mean tip deflection within [0, +11 %] of q L^4 / (8 D) (measured +5.81 %): a stiffness
//   deficit s shows as 1/s in deflection and 1/sqrt(s) in period, so the period's +5 % is
//   +10.25 % here; 0 is hard for the same reason (shear adds 1.3 % to the static deflection).
// - A clamped root that never moves.
TEST(OscillatingPlateValidation, PeriodAndDeflectionWithin5PercentAt16ParticlesAcross) {
    const CaseRun run =
        run_case_file("cases/oscillating_plate/oscillating_plate.toml", "oscillating_plate");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const auto [tip, root_motion] =
        read_tip_history(run.out, "oscillating_plate", ThinPlate::length, kSpacing);
    ASSERT_EQ(tip.size(), 526u); // 1.05 s at 2 ms
    const Swing swing = measure_swing(tip);
    ASSERT_GE(swing.periods, 3u);
    const ThinPlate plate = oscillating_plate_reference();
    const double reference_period = plate.period;
    const double static_tip = plate.static_tip;
    std::cout << "oscillating_plate: period " << swing.period << " s over " << swing.periods
              << " periods (" << 100.0 * (swing.period / reference_period - 1.0) << " %), mean tip "
              << swing.level << " m (" << 100.0 * (swing.level / static_tip - 1.0)
              << " %), root motion " << root_motion << " m\n";
    EXPECT_GT(swing.period / reference_period, 1.0);
    EXPECT_LT(swing.period / reference_period, 1.05);
    EXPECT_GT(swing.level / static_tip, 1.0);
    EXPECT_LT(swing.level / static_tip, 1.11);
    EXPECT_EQ(root_motion, 0.0);
}

} // namespace
