// `grainload trade` without running anything: the grid of --vary / --link / --reference, the
// most-accurate rule per axis, the analysis of a synthetic table (changes, budget, knee, failed
// and unstable runs as rows), trade.csv, reading summary.json back, and the advice `check`
// prints from a trade table. The references are the definitions of docs/user-guide/trade.md,
// worked by hand for each table.

#include "app/cost_estimate.hpp"
#include "app/trade/trade_grid.hpp"
#include "app/trade/trade_table.hpp"
#include "io/case_error.hpp"
#include "io/run_summary.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <sstream>
#include <unistd.h>

namespace grainload::app {
namespace {

namespace fs = std::filesystem;

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const io::CaseError& e) {
        return e.what();
    }
    return "no error";
}

TEST(TradeGrid, ParsesValuesWithUnitsBracketsAndQuotes) {
    const TradeAxis a = parse_trade_axis("sph.body[0].spacing=10 mm, 7.2 mm,5 mm", "--vary");
    EXPECT_EQ(a.key, "sph.body[0].spacing");
    EXPECT_EQ(a.values, (std::vector<std::string>{"10 mm", "7.2 mm", "5 mm"}));
    const TradeAxis b = parse_trade_axis("x.y=[1, 2],[3,4],\"a, b\"", "--vary");
    EXPECT_EQ(b.values, (std::vector<std::string>{"[1, 2]", "[3,4]", "\"a, b\""}));
    EXPECT_NE(error_of([] { parse_trade_axis("no_equals", "--vary"); }).find("KEY=V1,V2"),
              std::string::npos);
    EXPECT_NE(error_of([] { parse_trade_axis("a=1,,2", "--vary"); }).find("value 2 is empty"),
              std::string::npos);
    EXPECT_NE(error_of([] { parse_trade_axis("a=1,2,1", "--vary"); }).find("given twice"),
              std::string::npos);
}

TEST(TradeGrid, CartesianProductWithLinkedKeysAndStableIds) {
    std::vector<TradeAxis> axes{parse_trade_axis("sph.body[0].spacing=10 mm,5 mm", "--vary")};
    link_trade_axis(axes, parse_trade_axis("sph.wall[0].spacing=5 mm,2.5 mm", "--link"));
    axes.push_back(parse_trade_axis("material[0].stiffness_scale=1,0.1,0.01", "--vary"));
    const auto grid = trade_grid(axes);
    ASSERT_EQ(grid.size(), 6u);
    // First axis slowest; each axis' linked keys follow it.
    EXPECT_EQ(grid[0].id, "spacing_10mm-stiffness_scale_1");
    EXPECT_EQ(grid[5].id, "spacing_5mm-stiffness_scale_0.01");
    EXPECT_EQ(grid[4].overrides,
              (std::vector<std::string>{"sph.body[0].spacing=5 mm", "sph.wall[0].spacing=2.5 mm",
                                        "material[0].stiffness_scale=0.1"}));
    EXPECT_EQ(grid[4].index, (std::vector<std::size_t>{1, 1}));
    // Ids depend on the values only: a grid with one more value keeps the old ids.
    axes[1].values.push_back("0.001");
    const auto bigger = trade_grid(axes);
    EXPECT_EQ(bigger.size(), 8u);
    EXPECT_EQ(bigger[1].id, grid[1].id);
    // A --link needs a --vary before it and as many values.
    std::vector<TradeAxis> none;
    EXPECT_NE(error_of([&] {
                  link_trade_axis(none, parse_trade_axis("a=1", "--link"));
              }).find("must follow"),
              std::string::npos);
    EXPECT_NE(error_of([&] {
                  link_trade_axis(axes, parse_trade_axis("a=1,2", "--link"));
              }).find("give one per value"),
              std::string::npos);
    // Two axes with the same last name are told apart by the full key.
    const auto twin = trade_grid({parse_trade_axis("sph.body[0].spacing=1 mm", "--vary"),
                                  parse_trade_axis("sph.wall[0].spacing=2 mm", "--vary")});
    EXPECT_EQ(twin[0].id, "sph.body_0_.spacing_1mm-sph.wall_0_.spacing_2mm");
}

TEST(TradeGrid, MostAccurateValuePerAxis) {
    const std::vector<TradeAxis> axes{
        parse_trade_axis("sph.body[0].spacing=10 mm,0.0072 m,9 mm", "--vary"),
        parse_trade_axis("material[0].stiffness_scale=0.001,0.1,2", "--vary"),
        parse_trade_axis("sph.cfl_safety=0.3,0.1", "--vary"),
        parse_trade_axis("coupling.max_subcycles=0,10,5", "--vary"),
        parse_trade_axis("coupling.max_iterations=1,5", "--vary")};
    // 7.2 mm < 9 mm < 10 mm; |ln 2| = 0.69 < |ln 0.1| = 2.3; 0.1; 5 (0 is no limit); 5.
    EXPECT_EQ(most_accurate(axes), (std::vector<std::size_t>{1, 2, 1, 2, 1}));
    auto kernel = std::vector<TradeAxis>{
        parse_trade_axis("sph.kernel=cubic_spline,quintic_spline", "--vary")};
    EXPECT_NE(error_of([&] { most_accurate(kernel); }).find("--reference 'sph.kernel=VALUE'"),
              std::string::npos);
    set_trade_reference(kernel, "sph.kernel=quintic_spline");
    EXPECT_EQ(most_accurate(kernel), (std::vector<std::size_t>{1}));
    EXPECT_NE(error_of([&] {
                  set_trade_reference(kernel, "sph.kernel=wendland_c2");
              }).find("one of the --vary values"),
              std::string::npos);
    const std::vector<TradeAxis> mixed{parse_trade_axis("sph.body[0].spacing=10 mm,2 s", "--vary")};
    EXPECT_NE(error_of([&] { most_accurate(mixed); }).find("not a quantity comparable"),
              std::string::npos);
}

TradeResult result(const char* status, double elapsed, std::vector<double> values) {
    TradeResult r;
    r.status = status;
    r.exit_code = std::string(status) == "completed" ? 0 : 3;
    r.elapsed_s = elapsed;
    r.steps = static_cast<long long>(elapsed * 100);
    const char* names[] = {"height", "run_out", "outside"};
    for (std::size_t i = 0; i < values.size(); ++i) {
        r.figures.push_back({names[i], "m", values[i], std::nullopt});
    }
    return r;
}

TEST(TradeTable, KneeIsTheCheapestCompletedRunWithinBudget) {
    // Run 0 is the most accurate. Hand-worked changes against it (height 0.1, run-out 0.2,
    // outside 0): run 1 +1 % / -1.5 % / 0 -> within 2 %; run 2 +3 % -> out; run 3 is cheapest but
    // unstable; run 4 failed without figures; run 5 has 1 particle outside where the reference
    // has none -> +inf, out; run 6 within budget but slower than run 1.
    std::vector<TradeResult> results{result("completed", 100.0, {0.1, 0.2, 0.0}),
                                     result("completed", 20.0, {0.101, 0.197, 0.0}),
                                     result("completed", 5.0, {0.103, 0.2, 0.0}),
                                     result("unstable", 1.0, {0.1, 0.2, 0.0}),
                                     result("failed", 0.5, {}),
                                     result("completed", 4.0, {0.1, 0.2, 1.0}),
                                     result("completed", 30.0, {0.1005, 0.2, 0.0})};
    results[4].exit_code = 1;
    const TradeAnalysis a = analyse_trade(results, 0, {}, 0.02);
    EXPECT_EQ(a.figures, (std::vector<std::string>{"height", "run_out", "outside"}));
    ASSERT_TRUE(a.knee);
    EXPECT_EQ(*a.knee, 1u);
    EXPECT_EQ(a.within_budget, (std::vector<bool>{true, true, false, false, false, false, true}));
    EXPECT_NEAR(*a.change[1][0], 0.01, 1e-12);
    EXPECT_NEAR(*a.change[1][1], -0.015, 1e-12);
    EXPECT_EQ(*a.change[1][2], 0.0);
    EXPECT_TRUE(std::isinf(*a.change[5][2]));
    EXPECT_FALSE(a.change[4][0]);
    // Only the height counts: run 5 (4 s) becomes the knee.
    EXPECT_EQ(*analyse_trade(results, 0, {"height"}, 0.02).knee, 5u);
    // A tighter budget leaves the most accurate run and run 6 (+0.5 %).
    EXPECT_EQ(*analyse_trade(results, 0, {}, 0.006).knee, 6u);
    EXPECT_NE(error_of([&] {
                  analyse_trade(results, 0, {"angle"}, 0.02);
              }).find("has no figure 'angle' (it has: height, run_out, outside)"),
              std::string::npos);
    // The most accurate run did not complete: no changes, no knee.
    EXPECT_FALSE(analyse_trade(results, 3, {}, 0.02).knee);
}

class TempDir {
  public:
    TempDir() : path_(fs::temp_directory_path() / ("grainload_trade_" + std::to_string(getpid()))) {
        fs::create_directories(path_);
    }
    ~TempDir() { fs::remove_all(path_); }
    std::string operator/(const std::string& name) const { return (path_ / name).string(); }

  private:
    fs::path path_;
};

TEST(TradeTable, RoundOffEnsembleMeasuresChangesFromItsMeanWithAFloorOfTwoSigma) {
    // Runs 0 (most accurate), 1 and 2 are one setting under round-off: height 0.100, 0.104,
    // 0.096 -> mean 0.1, sample standard deviation sqrt((0 + 0.004^2 + 0.004^2) / 2) = 0.004,
    // 4 % -> tolerance 2 sigma = 8 % above the 2 % budget; run_out does not scatter (2 %).
    // Run 3 (+6 % height, +1.5 % run-out) is within; run 4 (+9 %) and run 5 (run-out +5 %) are
    // not. The members are the cheapest runs and still never the knee.
    TempDir dir;
    const std::vector<TradeAxis> axes{parse_trade_axis("sph.cfl_safety=0.1,0.2,0.3,0.4", "--vary")};
    auto grid = trade_grid(axes);
    for (TradeRun& member : noise_runs(grid[0], {0.0, -9.81, 0.0}, 2, 3)) {
        grid.push_back(std::move(member));
    }
    ASSERT_EQ(grid.size(), 6u);
    EXPECT_EQ(grid[5].id, "cfl_safety_0.1-noise_2");
    // "case.gravity=\"0 G m/s^2\"": G is gravity x (1 + 1e-8), then x (1 - 1e-8), to the last bit.
    const auto vertical = [](const std::string& assignment) {
        EXPECT_EQ(assignment.substr(0, 16), "case.gravity=\"0 ");
        return std::stod(assignment.substr(16));
    };
    EXPECT_EQ(vertical(grid[4].overrides.back()), -9.81 * (1.0 + 1e-8));
    EXPECT_EQ(vertical(grid[5].overrides.back()), -9.81 * (1.0 - 1e-8));
    std::vector<TradeResult> results{
        result("completed", 100.0, {0.100, 0.2}), result("completed", 10.0, {0.106, 0.203}),
        result("completed", 5.0, {0.109, 0.2}),   result("completed", 2.0, {0.1, 0.21}),
        result("completed", 1.0, {0.104, 0.2}),   result("completed", 1.0, {0.096, 0.2})};
    const TradeAnalysis a = analyse_trade(results, 0, {}, 0.02, {4, 5});
    EXPECT_NEAR(*a.reference[0], 0.1, 1e-15);
    EXPECT_NEAR(*a.noise[0], 0.04, 1e-12);
    EXPECT_NEAR(a.tolerance[0], 0.08, 1e-12);
    EXPECT_EQ(*a.noise[1], 0.0);
    EXPECT_EQ(a.tolerance[1], 0.02);
    EXPECT_NEAR(*a.change[1][0], 0.06, 1e-12);
    EXPECT_EQ(a.within_budget, (std::vector<bool>{true, true, false, false, true, true}));
    ASSERT_TRUE(a.knee);
    EXPECT_EQ(*a.knee, 1u);
    EXPECT_EQ(a.member(0), 0);
    EXPECT_EQ(a.member(5), 2);
    EXPECT_EQ(a.member(3), -1);
    // Without the ensemble run 1's +6 % is outside the budget: only the most accurate run stays.
    EXPECT_EQ(*analyse_trade(results, 0, {}, 0.02).knee, 0u);
    // A member that went unstable leaves two values: 0.100, 0.104 -> mean 0.102, sd 0.0028284.
    results[5].status = "unstable";
    const TradeAnalysis two = analyse_trade(results, 0, {"height"}, 0.02, {4, 5});
    EXPECT_NEAR(*two.noise[0], 0.004 / std::sqrt(2.0) / 0.102, 1e-12);
    write_trade_csv(dir / "trade.csv", axes, grid, results, two);
    std::ifstream in(dir / "trade.csv");
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(in, line);) {
        rows.push_back(split_csv_line(line));
    }
    EXPECT_EQ(rows[0][12], "noise");
    EXPECT_EQ(rows[0][17], "noise_member");
    EXPECT_EQ(rows[1][17], "0"); // the most accurate run's height row
    EXPECT_EQ(rows[11][0], "cfl_safety_0.1-noise_2");
    EXPECT_EQ(rows[11][1], "0.1"); // a member carries its setting's axis values
    EXPECT_EQ(rows[11][17], "2");
}

TEST(TradeTable, CsvHasARowPerRunAndFigureAndFailedRunsAsRows) {
    TempDir dir;
    const std::vector<TradeAxis> axes{parse_trade_axis("sph.cfl_safety=0.1,0.3,0.5", "--vary")};
    const auto grid = trade_grid(axes);
    std::vector<TradeResult> results{result("completed", 10.0, {0.1, 0.2}),
                                     result("completed", 4.0, {0.1001, 0.2}),
                                     result("failed", 1.0, {})};
    results[2].exit_code = 2;
    results[2].status = "bad_input";
    const TradeAnalysis a = analyse_trade(results, 0, {}, 0.02);
    write_trade_csv(dir / "trade.csv", axes, grid, results, a);
    std::ifstream in(dir / "trade.csv");
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(in, line);) {
        rows.push_back(split_csv_line(line));
    }
    ASSERT_EQ(rows.size(), 6u); // header, 2 + 2 figure rows, 1 row for the failed run
    EXPECT_EQ(rows[0][1], "sph.cfl_safety");
    EXPECT_EQ(rows[0].size(), 19u);
    for (const auto& row : rows) {
        EXPECT_EQ(row.size(), rows[0].size());
    }
    EXPECT_EQ(rows[3][0], "cfl_safety_0.3");
    EXPECT_EQ(rows[3][8], "height");
    EXPECT_EQ(rows[3][11], "0.001"); // (0.1001 - 0.1) / 0.1
    EXPECT_EQ(rows[3][18], "1");     // the knee
    EXPECT_EQ(rows[3][12], "");      // no round-off ensemble: no noise
    EXPECT_EQ(rows[3][13], "0.02");  // and the budget as the tolerance
    EXPECT_EQ(rows[5][2], "bad_input");
    EXPECT_EQ(rows[5][3], "2");
    EXPECT_EQ(rows[5][8], "");
    EXPECT_EQ(rows[1][16], "1"); // most accurate
    EXPECT_EQ(rows[1][17], "");  // no ensemble member
    // `check`'s advice reads the same file back, named after the case.
    fs::copy_file(dir / "trade.csv", dir / "case.trade.csv");
    const auto advice = trade_table_advice(dir / "case.toml");
    ASSERT_TRUE(advice);
    EXPECT_NE(advice->find("its knee cfl_safety_0.3 took 4 s against 10 s for the most accurate "
                           "run cfl_safety_0.1 (2.5x less), changing no figure by more than "
                           "0.10 % (height)"),
              std::string::npos)
        << *advice;
    EXPECT_FALSE(trade_table_advice(dir / "other.toml"));
}

TEST(TradeTable, ReadsSummaryJsonBack) {
    TempDir dir;
    io::RunSummary summary;
    summary.status = "unstable";
    summary.wall_time = 12.5;
    summary.steps = 1234;
    summary.points = 56;
    summary.results.push_back({
        "height",
        0.125,
        "m",
        0.1,
        "H0",
    });
    summary.results.push_back({"diverged", std::nan(""), "m", std::nullopt, ""});
    io::write_run_summary(summary, dir / "summary.json");
    const TradeResult r = read_trade_result(dir / "", 3, 20.0);
    EXPECT_EQ(r.status, "unstable");
    EXPECT_EQ(r.exit_code, 3);
    EXPECT_EQ(*r.wall_time_s, 12.5);
    EXPECT_EQ(*r.steps, 1234);
    EXPECT_EQ(*r.particles, 56);
    ASSERT_EQ(r.figures.size(), 2u);
    EXPECT_EQ(*r.figures[0].value, 0.125);
    EXPECT_DOUBLE_EQ(*r.figures[0].reference_error, 0.25);
    EXPECT_FALSE(r.figures[1].value); // null: a diverged figure
    // No summary: exit 2 is bad input, anything else a failure.
    EXPECT_EQ(read_trade_result(dir / "missing", 2, 1.0).status, "bad_input");
    EXPECT_EQ(read_trade_result(dir / "missing", -1, 1.0).status, "failed");
}

TEST(TradeTable, Budget) {
    EXPECT_DOUBLE_EQ(parse_budget("2%"), 0.02);
    EXPECT_DOUBLE_EQ(parse_budget("0.05"), 0.05);
    EXPECT_THROW(parse_budget("0%"), io::CaseError);
    EXPECT_THROW(parse_budget("two"), io::CaseError);
}

} // namespace
} // namespace grainload::app
