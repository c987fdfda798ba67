// `grainload trade` end to end on the CI free fall (4 x 4 x 8 particles, no interactions, runs
// of a fraction of a second): a failed run is a row of the table, a second invocation runs
// nothing new, a grown grid runs only the new settings, and a sweep directory refuses another
// case's settings. The figure compared is the free fall's centre height, which leapfrog
// integrates exactly for every time step (test_free_fall), so every completed run is within
// budget of the most accurate one.

#include "io/json_value.hpp"
#include "support/cli_runner.hpp"
#include "support/test_folder.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <sstream>
#include <vector>

namespace {

using namespace grainload::testing;
namespace fs = std::filesystem;

const std::string kCase = "'" + source_path("cases/free_fall/free_fall_small.toml") + "'";

/// The rows of trade.csv as maps from column to cell (no quoted commas in this sweep).
std::vector<std::map<std::string, std::string>> read_rows(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    std::stringstream names(line);
    for (std::string name; std::getline(names, name, ',');) {
        header.push_back(name);
    }
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        std::stringstream cells(line + ",");
        std::map<std::string, std::string> row;
        for (const std::string& name : header) {
            std::getline(cells, row[name], ',');
        }
        rows.push_back(row);
    }
    return rows;
}

/// Each run's centre_height row (or its row without figures: a run that failed), by run.
std::map<std::string, std::map<std::string, std::string>> rows_by_run(const std::string& path) {
    std::map<std::string, std::map<std::string, std::string>> by_run;
    for (const auto& row : read_rows(path)) {
        if (row.at("figure") == "centre_height" || row.at("figure").empty()) {
            by_run[row.at("run")] = row;
        }
    }
    return by_run;
}

TEST(TradeCli, FailedRunsAreRowsAndAResumedSweepRunsNothingNew) {
    const std::string out = test_folder("trade_cli");
    fs::remove_all(out);
    const std::string sweep = "trade " + kCase + " --out '" + out +
                              "' --reference 'sph.time_step=1 ms' --jobs 2 --threads 1"
                              " --figures centre_height --vary 'sph.time_step=1 ms,3 ms,fast";
    const std::string end = "'";
    const auto first = run_cli(sweep + end, out + ".log");
    ASSERT_EQ(first.exit_code, 0) << first.output;
    EXPECT_NE(first.output.find("3 runs, 0 finished earlier, 3 to run"), std::string::npos)
        << first.output;
    // Two figures (centre_height, max_position_error) per completed run, one failed row.
    ASSERT_EQ(read_rows(out + "/trade.csv").size(), 5u);
    auto by_run = rows_by_run(out + "/trade.csv");
    EXPECT_EQ(by_run["time_step_fast"]["status"], "bad_input");
    EXPECT_EQ(by_run["time_step_fast"]["exit_code"], "2");
    EXPECT_EQ(by_run["time_step_fast"]["figure"], "");
    EXPECT_EQ(by_run["time_step_1ms"]["most_accurate"], "1");
    EXPECT_EQ(by_run["time_step_3ms"]["status"], "completed");
    EXPECT_EQ(by_run["time_step_3ms"]["figure"], "centre_height");
    EXPECT_EQ(by_run["time_step_3ms"]["steps"], "80"); // 4 steps per 10 ms frame
    EXPECT_EQ(by_run["time_step_3ms"]["within_budget"], "1");
    // Leapfrog is exact here: the change is round-off and the figure meets its own reference.
    EXPECT_LT(std::abs(std::stod(by_run["time_step_3ms"]["change"])), 1e-12);
    EXPECT_LT(std::stod(by_run["time_step_3ms"]["reference_error"]), 1e-12);
    EXPECT_EQ(by_run["time_step_1ms"]["knee"] == "1" || by_run["time_step_3ms"]["knee"] == "1",
              true);
    const bool plotted = fs::exists(out + "/trade.svg");
    EXPECT_TRUE(plotted || first.output.find("plot skipped") != std::string::npos) << first.output;

    const auto stamp = fs::last_write_time(out + "/time_step_1ms/summary.json");
    const auto second = run_cli(sweep + end, out + ".log");
    ASSERT_EQ(second.exit_code, 0) << second.output;
    EXPECT_NE(second.output.find("3 runs, 3 finished earlier, 0 to run"), std::string::npos)
        << second.output;
    EXPECT_EQ(fs::last_write_time(out + "/time_step_1ms/summary.json"), stamp);

    const auto grown = run_cli(sweep + ",2 ms" + end, out + ".log");
    ASSERT_EQ(grown.exit_code, 0) << grown.output;
    EXPECT_NE(grown.output.find("4 runs, 3 finished earlier, 1 to run"), std::string::npos)
        << grown.output;

    const auto other = run_cli(sweep + end + " --set 'case.end_time=0.1 s'", out + ".log");
    EXPECT_EQ(other.exit_code, 2) << other.output;
    EXPECT_NE(other.output.find("its runs cannot be reused"), std::string::npos) << other.output;
    fs::remove_all(out);
}

TEST(TradeCli, NoiseEnsemblePerturbsGravityAndMeasuresTheScatter) {
    // --noise 3: the most accurate run and two members with gravity x (1 + 1e-8) and
    // x (1 - 1e-8). The free fall's centre height is z0 + vz t - g t^2 / 2 (leapfrog exact), so
    // the members move it by -+1e-8 g t^2 / 2 and the sample standard deviation over the three
    // is exactly 1e-8 g t^2 / 2 = 1.962e-9 m at t = 0.2 s, over the mean 1.3038 m. summary.json
    // writes 12 significant digits: each value is rounded by up to 5e-12 m, which moves the
    // 2e-9 m deviation by up to 0.5 %; hence 1 %. A case without gravity is refused.
    const std::string out = test_folder("trade_noise");
    fs::remove_all(out);
    const auto result = run_cli("trade " + kCase + " --out '" + out +
                                    "' --jobs 2 --threads 1 --figures centre_height --noise 3"
                                    " --vary 'sph.time_step=1 ms,2 ms'",
                                out + ".log");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("4 runs, 0 finished earlier, 4 to run"), std::string::npos)
        << result.output;
    auto by_run = rows_by_run(out + "/trade.csv");
    ASSERT_EQ(by_run.size(), 4u);
    EXPECT_EQ(by_run["time_step_1ms-noise_2"]["noise_member"], "2");
    EXPECT_EQ(by_run["time_step_1ms"]["noise_member"], "0");
    EXPECT_EQ(by_run["time_step_2ms"]["noise_member"], "");
    const double expected = 1e-8 * 9.81 * 0.2 * 0.2 / 2.0 / 1.3038;
    EXPECT_NEAR(std::stod(by_run["time_step_2ms"]["noise"]), expected, 0.01 * expected);
    EXPECT_EQ(by_run["time_step_2ms"]["within_budget"], "1");
    const auto record =
        grainload::io::read_json_file(out + "/time_step_1ms-noise_1/trade_run.json");
    const std::string gravity = record.find("overrides")->array.back().string;
    ASSERT_EQ(gravity.substr(0, 18), "case.gravity=\"0 0 ");
    EXPECT_EQ(std::stod(gravity.substr(18)), -9.81 * (1.0 + 1e-8)); // %.17g: to the last bit

    const auto weightless = run_cli("trade " + kCase + " --out '" + out +
                                        "_g0' --noise 2 --vary 'sph.time_step=1 ms,2 ms'"
                                        " --set 'case.gravity=0 0 0 m/s^2'",
                                    out + ".log");
    EXPECT_EQ(weightless.exit_code, 2) << weightless.output;
    EXPECT_NE(weightless.output.find("this case has no gravity"), std::string::npos)
        << weightless.output;
    fs::remove_all(out);
    fs::remove_all(out + "_g0");
}

// A sweep whose runs all fail is no trade: here a misspelt key that every run refuses (exit 2).
// The sweep exits with the first run's code and shows its error, instead of a table of failures
// and exit 0.
TEST(TradeCli, ASweepWhoseRunsAllFailExitsWithTheFirstRunsError) {
    const std::string out = test_folder("trade_all_fail");
    fs::remove_all(out);
    const auto result = run_cli("trade " + kCase + " --out '" + out +
                                    "' --jobs 2 --threads 1 --vary 'sph.spacng=10 mm,20 mm'"
                                    " --reference 'sph.spacng=10 mm'",
                                out + ".log");
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("every run failed"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("unknown key 'sph.spacng'"), std::string::npos) << result.output;
    fs::remove_all(out);
}

// A misspelt key has no accuracy rule either; asking for --reference would send the user the
// wrong way. The sweep loads the case with its first values and refuses the key as
// `grainload run --set` does: exit 2, naming the key and the flag that gave it, before any run.
TEST(TradeCli, AMisspeltKeyWithoutReferenceIsNamedAsUnknown) {
    const std::string out = test_folder("trade_misspelt");
    fs::remove_all(out);
    const auto result = run_cli("trade " + kCase + " --out '" + out +
                                    "' --vary 'sph.kernal=cubic_spline,wendland_c2'",
                                out + ".log");
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("--vary sph.kernal=cubic_spline:1:"), std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("unknown key 'sph.kernal'"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("--reference"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(out + "/kernal_cubic_spline")) << "no run is started";
    fs::remove_all(out);
}

// A key the case reads but no rule ranks (the body's launch velocity) needs --reference. (The
// kernel, which this case without interactions does not read, is a key it does not know.)
TEST(TradeCli, RefusesAnAxisWithoutAccuracyRule) {
    const auto result = run_cli("trade " + kCase + " --out '" + test_folder("trade_norule") +
                                    "' --vary 'sph.body[0].velocity=0.5 0 2 m/s,0 0 2 m/s'",
                                test_folder("trade_norule.log"));
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("--reference 'sph.body[0].velocity=VALUE'"), std::string::npos)
        << result.output;
}

} // namespace
