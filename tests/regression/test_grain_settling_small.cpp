// DEM beads settling in a box, run from the command line as a user runs it: at rest the walls
// carry their weight; a run killed and restarted writes what the uninterrupted run writes.

#include "io/json_value.hpp"
#include "support/cli_runner.hpp"
#include "support/gold_summary.hpp"
#include "support/interrupted_run.hpp"
#include "support/test_folder.hpp"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>

namespace {

using namespace grainload::testing;

constexpr const char* kCase = "cases/grain_settling/grain_settling_small.toml";

/// The figure `name` of summary.json's results: its value, or its reference with `what`.
double figure(const grainload::io::JsonValue& summary, const std::string& name,
              const char* what = "value") {
    const grainload::io::JsonValue* entry = summary.find("results")->find(name);
    return entry != nullptr ? entry->number_at(what).value_or(NAN) : NAN;
}

// At rest the walls carry the grains' weight: static equilibrium, the reference the model
// states beside the figure. What still moves at 0.6 s (kinetic energy 2e-7 J against the
// fall's 0.17 J) changes the load by its momentum's rate: measured 3.7e-4 of the weight, bound
// 2e-3. The mean contact count of grains with each other, walls left out, lies below the
// isostatic 6 of frictionless spheres and near the 4 of very frictional ones (Silbert et al.
// 2002, Phys. Rev. E 65); the walls' neighbours lower it (measured 3.7): bound [3, 6].
TEST(GrainSettlingSmall, AtRestTheWallsCarryTheGrainsWeight) {
    const std::string out = test_folder("grain_settling_small");
    std::filesystem::remove_all(out);
    const auto result =
        run_cli("run '" + source_path(kCase) + "' --out '" + out + "'", out + ".log");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const auto summary = grainload::io::read_json_file(out + "/summary.json");
    const double weight = figure(summary, "walls_load_along_gravity", "reference");
    EXPECT_NEAR(figure(summary, "walls_load_along_gravity"), weight, 2e-3 * weight);
    EXPECT_LT(figure(summary, "kinetic_energy"), 1e-6);
    EXPECT_GT(figure(summary, "coordination_number"), 3.0);
    EXPECT_LT(figure(summary, "coordination_number"), 6.0);
    EXPECT_LT(figure(summary, "deepest_overlap"), 0.01);
    expect_matches_gold(out, kCase);
}

// SIGKILL at random moments after the first checkpoint and a restart: frames, wall_forces.csv,
// log and summary equal the uninterrupted run's (grains, their springs and the neighbour list
// restored bit for bit).
TEST(GrainSettlingSmall, KilledAndRestartedReproducesTheUninterruptedRun) {
    const std::vector<std::string> arguments = {
        "run",   source_path(kCase),           "--set",     "case.end_time=0.2 s",
        "--set", "case.output_interval=10 ms", "--threads", "1"};
    expect_restarts_reproduce_the_run(arguments, "grain_settling", 2);
}

} // namespace
