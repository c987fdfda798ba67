#include "support/case_runner.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace grainload::testing {
namespace {

/// The CI plane-wedge hopper (cases/hopper_discharge/hopper_discharge_small.toml) with its gate
/// removed at `remove_at` (a time, or "settled") and, when `settle` is set, an [sph.settle]
/// table with kinetic_energy_fraction = 1e-3.
std::string hopper_variant(const std::string& name, const std::string& remove_at, bool settle) {
    const std::string file = test_folder(name) + ".toml";
    std::string text = read_file(source_path("cases/hopper_discharge/hopper_discharge_small.toml"));
    text = std::regex_replace(text, std::regex("remove_at = \"0.4 s\""),
                              "remove_at = \"" + remove_at + "\"");
    if (settle) {
        text += "\n[sph.settle]\nkinetic_energy_fraction = 1e-3\n";
    }
    std::ofstream(file) << text;
    return file;
}

CliResult run_to(const std::string& file, const std::string& out, const std::string& end,
                 const std::string& extra = "") {
    return run_cli("run '" + file + "' --set 'case.end_time=" + end + "' --out '" + out + "'" +
                       extra,
                   out + ".log");
}

// The gate leaves at the end of the step that settles the fill (its kinetic energy below 1e-3
// of its peak, measured 0.4037 s after the fill is released: 0.12 J of a 127 J peak). The
// reference is the same hopper with the gate removed at the logged settle time as a fixed
// remove_at (the time written to 17 digits): both remove the gate after the same step, so
// both runs must end bit for bit alike at 0.6 s; and the log names the settle time.
TEST(SettlePhase, GateOpensWhenTheFillSettlesAsAtTheSameFixedTime) {
    const std::string base = test_folder("settle");
    std::filesystem::remove_all(base + "_phase");
    std::filesystem::remove_all(base + "_fixed");
    const auto phase =
        run_to(hopper_variant("settle_phase", "settled", true), base + "_phase", "0.6 s");
    ASSERT_EQ(phase.exit_code, 0) << phase.output;
    const std::string summary = read_file(base + "_phase/summary.json");
    const double settled = result_value(summary, "settle_time");
    constexpr double kEarliest = 0.2; // the released fill is still moving: KE 10-100 J
    constexpr double kLatest = 0.6;
    EXPECT_GT(settled, kEarliest);
    EXPECT_LT(settled, kLatest);
    EXPECT_NE(read_file(base + "_phase/log.txt").find("settled at t = "), std::string::npos);
    EXPECT_EQ(result_value(summary, "wall_gate_force_y"), 0.0) << "the gate is gone";
    EXPECT_GT(result_value(summary, "discharged_mass"), 0.0);
    // The fixed-time reference, from summary.json's 12 digits: within 1e-12 relative of the
    // step end, which the removal tolerance (sph_model_outlets.cpp) treats as that step.
    char time[64];
    std::snprintf(time, sizeof time, "%.17g s", settled);
    const auto fixed =
        run_to(hopper_variant("settle_fixed", time, false), base + "_fixed", "0.6 s");
    ASSERT_EQ(fixed.exit_code, 0) << fixed.output;
    const std::string reference = read_file(base + "_fixed/summary.json");
    for (const char* figure : {"discharged_mass", "kinetic_energy", "wall_left_force_x"}) {
        EXPECT_EQ(result_value(summary, figure), result_value(reference, figure)) << figure;
    }
}

// Restart across the phase change: stopped at 0.3 s (before the settle time), restarted to
// 0.6 s, the run settles at the same step and ends bit for bit like the whole run: the
// checkpoint holds the watch's peak and settle time.
TEST(SettlePhase, RestartAcrossThePhaseChangeReproducesTheUninterruptedRun) {
    const std::string base = test_folder("settle_restart");
    std::filesystem::remove_all(base + "_whole");
    std::filesystem::remove_all(base + "_split");
    const std::string file = hopper_variant("settle_restart", "settled", true);
    ASSERT_EQ(run_to(file, base + "_whole", "0.6 s").exit_code, 0);
    ASSERT_EQ(run_to(file, base + "_split", "0.3 s").exit_code, 0);
    const auto second =
        run_to(file, base + "_split", "0.6 s", " --restart '" + base + "_split/checkpoint.bin'");
    ASSERT_EQ(second.exit_code, 0) << second.output;
    const std::string a = read_file(base + "_whole/summary.json");
    const std::string b = read_file(base + "_split/summary.json");
    for (const char* figure : {"settle_time", "settle_peak_kinetic_energy", "discharged_mass",
                               "kinetic_energy", "energy_balance_error"}) {
        EXPECT_EQ(result_value(a, figure), result_value(b, figure)) << figure;
    }
}

} // namespace
} // namespace grainload::testing
