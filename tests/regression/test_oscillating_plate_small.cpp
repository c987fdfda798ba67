#include "support/case_runner.hpp"
#include "support/gold_summary.hpp"
#include "support/plate_tip.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace {

using namespace grainload::testing;

constexpr double kSpacing = 0.0025;
constexpr double kInterval = 0.002; // output_interval of the case

// The CI version of oscillating_plate: Gray, Monaghan & Swift's cantilever plate in the
// total-Lagrangian formulation, 8 particles across H, released under sudden gravity g = 1 m/s^2
// from the case file through the CLI. Thin-plate theory (plane strain): first-mode period
// T = 0.2540 s, static tip deflection q L^4 / (8 D) = 2.526 mm, the level the tip swings about.
// At 8 particles across H the SPH plate is too soft in bending by the two first-order deficits
// of docs/validation/oscillating_plate.md (one-sided surface rows, compliant root): the
// mode-shape verification test (OscillatingPlate) measures +9.65 % in period with the same
// spacing. Asserted: the period between the two downward crossings of the swing's mid level
// within [0, +12 %] of T, as in that test; the mid level (the static deflection) within
// [0, +25 %] of q L^4 / (8 D): a stiffness deficit s shows as 1/s both in the static deflection
// and in the period squared (measured here 1.202 and 1.0961^2 = 1.201), so the period's +12 % is
// +25 % here; and a root that never moves.
TEST(OscillatingPlateSmall, TotalLagrangianPlateSwingsAtThinPlateFrequencyFromTheCli) {
    const CaseRun run = run_case_file("cases/oscillating_plate/oscillating_plate_small.toml",
                                      "oscillating_plate_small", "--threads 1");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const auto [tip, root_motion] =
        read_tip_history(run.out, "oscillating_plate_small", ThinPlate::length, kSpacing);
    ASSERT_EQ(tip.size(), 281u); // 0.56 s at 2 ms
    const auto [low, high] = std::minmax_element(tip.begin(), tip.end());
    const double level = 0.5 * (*low + *high);
    const auto down = crossings_down(tip, level, kInterval);
    ASSERT_GE(down.size(), 2u);
    const double period = down[1] - down[0];
    const ThinPlate plate = oscillating_plate_reference();
    const double reference_period = plate.period;
    const double static_tip = plate.static_tip;
    std::cout << "oscillating_plate_small: period " << period << " s ("
              << 100.0 * (period / reference_period - 1.0) << " %), mid level " << level << " m ("
              << 100.0 * (level / static_tip - 1.0) << " %), root motion " << root_motion << " m\n";
    EXPECT_GT(period / reference_period, 1.0);
    EXPECT_LT(period / reference_period, 1.12);
    EXPECT_GT(level / static_tip, 1.0);
    EXPECT_LT(level / static_tip, 1.25);
    EXPECT_EQ(root_motion, 0.0);
    expect_matches_gold(run.out, "cases/oscillating_plate/oscillating_plate_small.toml");
}

} // namespace
