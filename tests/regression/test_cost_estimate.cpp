// The cost estimate of `grainload check` (app/cost_estimate.hpp) against the steps runs take,
// read from the estimate block each run writes into its summary.json. A fixed step must be
// counted exactly (the estimate lands on the output instants as the time loop does). A CFL step
// h / (c + |v|) can only shrink as the material speeds up, so the actual steps exceed the
// estimate from t = 0 by at most the ratio (c + v_max) / c: for the CI column collapse (E =
// 5.84 MPa, c = 62.07 m/s; a 0.1 m column whose particles cannot outrun the free-fall speed
// sqrt(2 g H0) = 1.40 m/s by more than a factor 2) that is 1 + 2.8 / 62.07 = 1.045.

#include "io/json_value.hpp"
#include "support/cli_runner.hpp"
#include "support/test_folder.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <gtest/gtest.h>

namespace {

using namespace grainload::testing;

grainload::io::JsonValue run_and_read(const std::string& arguments, const std::string& name) {
    const std::string out = test_folder(name);
    std::filesystem::remove_all(out);
    const auto result =
        run_cli("run " + arguments + " --threads 1 --out '" + out + "'", out + ".log");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return grainload::io::read_json_file(out + "/summary.json");
}

TEST(CostEstimate, FixedStepIsCountedExactly) {
    // 3 ms steps in 10 ms frames: 4 steps per frame (the last one cut to the frame), 80 in all.
    const auto summary = run_and_read("'" + source_path("cases/free_fall/free_fall_small.toml") +
                                          "' --set 'sph.time_step=3 ms'",
                                      "cost_free_fall");
    const auto* estimate = summary.find("estimate");
    ASSERT_NE(estimate, nullptr);
    EXPECT_EQ(estimate->number_at("steps"), 80.0);
    EXPECT_EQ(summary.number_at("steps"), 80.0);
    EXPECT_EQ(estimate->number_at("steps_ratio"), 1.0);
    EXPECT_GT(*estimate->number_at("wall_time_s"), 0.0);
}

TEST(CostEstimate, CflStepCountWithinTheSpeedBound) {
    constexpr double kSpeedBound = 1.0 + 2.0 * 1.40 / 62.07;
    const auto summary =
        run_and_read("'" + source_path("cases/column_collapse_2d/column_collapse_2d_small.toml") +
                         "' --set 'case.end_time=0.1 s'",
                     "cost_collapse");
    const auto* estimate = summary.find("estimate");
    ASSERT_NE(estimate, nullptr);
    const double ratio = *estimate->number_at("steps_ratio");
    RecordProperty("steps_ratio", std::to_string(ratio));
    EXPECT_GE(ratio, 1.0);
    EXPECT_LE(ratio, kSpeedBound);
}

TEST(CostEstimate, CheckPrintsTheEstimate) {
    const std::string log = test_folder("cost_check.log");
    const auto result =
        run_cli("check '" + source_path("cases/free_fall/free_fall_small.toml") + "'", log);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("200 steps to the end time"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("estimated wall time"), std::string::npos) << result.output;
}

// A scene filled by a source costs what it will hold, not what it starts with: the CI slot
// silo starts with one row (15 particles) and its source creates 400 kg/(m s) for 1.7 s of
// 0.9375 kg/m particles, 725 by the rate but at most its 15 x 48 = 720 sites, at an even rate:
// a particle created at t is there for 3 s - t, so the run holds 720 (3 - 0.85) / 3 = 516 more
// on average (the printed figure, rounded; exact arithmetic, so to the unit).
TEST(CostEstimate, SourcesAddTheParticlesTheyCreateAveragedOverTheRun) {
    const std::string log = test_folder("cost_source.log");
    const auto result =
        run_cli("check '" + source_path("cases/silo/silo_rest_small.toml") + "'", log);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const double expected = 720.0 * (3.0 - 0.85) / 3.0;
    char text[32];
    std::snprintf(text, sizeof text, "sources: %.0f particles", expected);
    EXPECT_NE(result.output.find(text), std::string::npos) << result.output;
    // No sink here; the discharge's one sink is named with what the estimate does not count.
    EXPECT_EQ(result.output.find("sinks:"), std::string::npos) << result.output;
    const auto discharge =
        run_cli("check '" + source_path("cases/silo_hopper/silo_hopper_small.toml") + "'",
                log + ".discharge");
    ASSERT_EQ(discharge.exit_code, 0) << discharge.output;
    EXPECT_NE(discharge.output.find("sinks: 1; the particles they take are counted to the end "
                                    "time (no outlet_width declared)"),
              std::string::npos)
        << discharge.output;
}

// A sink with a declared outlet takes its particles at Beverloo's rate from the opening: the CI
// hopper (50 mm, 300 kg/m^3: 0.75 kg/m a grain) holds M = 0.75 n kg/m; its 0.4 m slot drains
// spheres of 65 mm (the material's grain_size): W = 1.03 * 300 * sqrt(9.81) * (0.4 - 1.5 *
// 0.065)^1.5 = 161.02 kg/m/s (printed to 4 digits) from 0.4 s, empty tau = M / W later; over the
// run's 3 s the grains taken average n (tau / 2 + (2.6 - tau)) / 3 (the printed figure, rounded: to
// the unit).
TEST(CostEstimate, ADeclaredOutletTakesItsParticlesAtBeverloosRate) {
    const std::string log = test_folder("cost_outlet.log");
    const auto result = run_cli(
        "check '" + source_path("cases/hopper_discharge/hopper_discharge_small.toml") + "'", log);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    long long particles = 0;
    long long walls = 0;
    const auto cost = result.output.find("cost: ");
    ASSERT_NE(cost, std::string::npos) << result.output;
    ASSERT_EQ(std::sscanf(result.output.c_str() + cost, "cost: %lld SPH particles (%lld of them",
                          &particles, &walls),
              2);
    const double grains = static_cast<double>(particles - walls);
    const double mass = 0.75 * grains;
    const double rate = 1.03 * 300.0 * std::sqrt(9.81) * std::pow(0.4 - 1.5 * 0.065, 1.5);
    const double tau = mass / rate;
    ASSERT_LT(tau, 2.6) << "the hopper empties before the end";
    const double expected = grains * (0.5 * tau + (2.6 - tau)) / 3.0;
    char text[128];
    std::snprintf(text, sizeof text,
                  "sinks: 1; their outlets' Beverloo rate 161 kg/m/s from 0.4 s takes %.0f "
                  "particles",
                  expected);
    EXPECT_NE(result.output.find(text), std::string::npos) << result.output;
}

} // namespace
