// The DEM hopper's CI version through the command line: a gate that leaves, a sink that takes
// every grain, the mass books, and a kill and restart across the opening.

#include "support/case_runner.hpp"
#include "support/csv_rows.hpp"
#include "support/gold_summary.hpp"
#include "support/interrupted_run.hpp"

#include <gtest/gtest.h>

namespace {

using namespace grainload::testing;

constexpr const char* kCase = "cases/hopper_discharge/hopper_discharge_dem_small.toml";

// 500 spheres rest on the gate until it leaves at 1.5 s; by 2.7 s the sink has taken all of
// them (the hopper's walls are steeper than the 16.7 deg the friction holds, so nothing stays).
// The mass audit closes to the round-off of 500 grain masses; nothing leaves before the gate
// opens.
TEST(HopperDischargeDemSmall, TheGateOpensAndTheSinkTakesEveryGrain) {
    const CaseRun run = run_case_file(kCase, "hopper_discharge_dem_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_EQ(result_value(summary, "grains"), 0.0);
    EXPECT_NEAR(result_value(summary, "discharged_mass"), result_value(summary, "initial_mass"),
                500 * 2.2e-16 * result_value(summary, "initial_mass"));
    EXPECT_LT(std::abs(result_value(summary, "mass_audit_error")), 500 * 2.2e-16);
    for (const auto& [time, mass] : discharge_rows(run.out)) {
        if (time <= 1.5) {
            EXPECT_EQ(mass, 0.0) << "grains left at " << time << " s, before the gate opened";
        }
    }
    EXPECT_NE(read_file(run.out + "/log.txt").find("wall gate removed at t = 1.5 s"),
              std::string::npos);
    expect_matches_gold(run.out, kCase);
}

// A run to 1.8 s (the gate leaves at 1.5 s, the first grains reach the sink after it) killed at
// random moments and restarted: every file equals the uninterrupted run's, discharge.csv and
// the log's "wall gate removed" included.
TEST(HopperDischargeDemSmall, KilledAcrossTheOpeningAndRestartedReproducesTheRun) {
    const std::vector<std::string> arguments = {
        "run",   source_path(kCase),           "--set",     "case.end_time=1.8 s",
        "--set", "case.output_interval=0.1 s", "--threads", "1"};
    expect_restarts_reproduce_the_run(arguments, "hopper_discharge_dem", 2);
}

} // namespace
