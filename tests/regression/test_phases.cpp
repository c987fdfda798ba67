#include "support/case_runner.hpp"
#include "support/csv_rows.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace grainload::testing {
namespace {

// The CI plane-wedge hopper (cases/hopper_discharge/hopper_discharge_small.toml) with a slide
// gate instead of one removed at 0.4 s: the gate is pulled along +x, reaching 2 m/s over 10 ms,
// from the start of the phase `discharge`.
const char* const kSlideHistory =
    "velocity_history = [[\"0 s\", \"0 0 m/s\"], [\"0.01 s\", \"2 0 m/s\"], "
    "[\"10 s\", \"2 0 m/s\"]]\n";

// Three phases: `hold` ends at a stated time, `settle` when the fill's kinetic energy falls
// below 1e-3 of its peak, `discharge` runs to the end; the gate opens when `discharge` begins.
const char* const kPhaseTable = R"(
[[phase]]
name = "hold"
end = "0.1 s"

[[phase]]
name = "settle"
end = "settled"
kinetic_energy_fraction = 1e-3

[[phase]]
name = "discharge"
)";

std::string hopper_with_gate(const std::string& name, const std::string& gate_keys,
                             const std::string& extra) {
    const std::string file = test_folder(name) + ".toml";
    std::string text = read_file(source_path("cases/hopper_discharge/hopper_discharge_small.toml"));
    text = std::regex_replace(text, std::regex("remove_at = \"0.4 s\"[^\n]*\n"), gate_keys);
    std::ofstream(file) << text << extra;
    return file;
}

std::string phase_hopper(const std::string& name) {
    return hopper_with_gate(
        name, "history_start = \"phase:discharge\"\n" + std::string(kSlideHistory), kPhaseTable);
}

CliResult run_to(const std::string& file, const std::string& out, const std::string& end,
                 const std::string& extra = "") {
    std::filesystem::remove_all(out);
    return run_cli("run '" + file + "' --set 'case.end_time=" + end + "' --out '" + out + "'" +
                       extra,
                   out + ".log");
}

/// summary.json's record of phase `name` as written: start, end, ended_by (empty: missing).
struct PhaseText {
    std::string start, end, ended_by;
    bool empty() const { return start.empty(); }
    bool operator==(const PhaseText&) const = default;
};

PhaseText phase_record(const std::string& summary, const std::string& name) {
    const std::regex pattern("\\{\"name\": \"" + name +
                             "\", \"start\": ([^,]+), \"end\": ([^,]+), \"ended_by\": ([^}]+)\\}");
    std::smatch match;
    EXPECT_TRUE(std::regex_search(summary, match, pattern)) << name << "\n" << summary;
    return match.empty() ? PhaseText{} : PhaseText{match[1], match[2], match[3]};
}

std::string time_text(double seconds) {
    char text[64];
    std::snprintf(text, sizeof text, "\"%.17g s\"", seconds);
    return text;
}

constexpr const char* kFigures[] = {
    "discharged_mass",      "kinetic_energy", "wall_left_force_x",         "wall_gate_force_y",
    "energy_balance_error", "settle_time",    "settle_peak_kinetic_energy"};

// The phase table against the same scene written with the keys it replaces: [sph.settle] with
// after = 0.1 s (the end of `hold`) and the gate's history at absolute times, its points placed
// at the settle time the phase run logged (summary.json writes it to 17 digits, which read
// back as the same double). The gate moves with the same numbers in both (a history holds its
// first value before its first point in both forms), so the runs must agree bit for bit at
// 0.9 s, with the sand running out (the first particles reach the sink between 0.70 and 0.75 s,
// the gate pulled 0.6 m by then): the figures, and the last frame's particles and gate byte for
// byte (their VTK files hold positions, velocities and stresses in binary); the phases end at 0.1 s
// (the stated time) and at the settle time, which lies between 0.2 and 0.6 s as on the removed-gate
// hopper (0.404 s, tests/regression/test_settle_phase.cpp).
TEST(Phases, TableRunsAsTheEquivalentOldKeys) {
    const std::string base = test_folder("phases");
    const auto phase = run_to(phase_hopper("phases_table"), base + "_table", "0.9 s");
    ASSERT_EQ(phase.exit_code, 0) << phase.output;
    const std::string summary = read_file(base + "_table/summary.json");
    const auto hold = phase_record(summary, "hold");
    const auto settle = phase_record(summary, "settle");
    const auto discharge = phase_record(summary, "discharge");
    ASSERT_FALSE(hold.empty() || settle.empty() || discharge.empty());
    EXPECT_EQ(hold.end, "0.10000000000000001") << "ends at the stated 0.1 s exactly";
    EXPECT_EQ(hold.ended_by, "\"time\"");
    EXPECT_EQ(settle.start, hold.end);
    EXPECT_EQ(settle.ended_by, "\"settled\"");
    EXPECT_EQ(discharge.start, settle.end);
    EXPECT_EQ(discharge.end, "null");
    const double settled = std::stod(settle.end);
    EXPECT_GT(settled, 0.2);
    EXPECT_LT(settled, 0.6);
    const std::string log = read_file(base + "_table/log.txt");
    EXPECT_NE(log.find("phase \"settle\" ended at t = "), std::string::npos) << log;
    EXPECT_NE(log.find("phase \"discharge\" begins"), std::string::npos) << log;
    EXPECT_GT(result_value(summary, "discharged_mass"), 0.0) << "the gate opened";

    const std::string old_history = "velocity_history = [[\"0 s\", \"0 0 m/s\"], [" +
                                    time_text(settled) + ", \"0 0 m/s\"], [" +
                                    time_text(settled + 0.01) + ", \"2 0 m/s\"], [" +
                                    time_text(settled + 10.0) + ", \"2 0 m/s\"]]\n";
    const auto old = run_to(hopper_with_gate("phases_old", old_history,
                                             "\n[sph.settle]\nkinetic_energy_fraction = 1e-3\n"
                                             "after = \"0.1 s\"\n"),
                            base + "_old", "0.9 s");
    ASSERT_EQ(old.exit_code, 0) << old.output;
    const std::string reference = read_file(base + "_old/summary.json");
    for (const char* figure : kFigures) {
        EXPECT_EQ(result_value(summary, figure), result_value(reference, figure)) << figure;
    }
    for (const char* block : {"fill.vtp", "wall_gate.vtp"}) {
        const std::string frame = "/frames/hopper_discharge_small_000018/" + std::string(block);
        const std::string ours = read_file(base + "_table" + frame);
        ASSERT_FALSE(ours.empty()) << frame << " missing";
        EXPECT_TRUE(ours == read_file(base + "_old" + frame)) << block;
    }
}

// Restart across both phase boundaries: stopped at 0.3 s (inside `settle`, the watch's peak in
// the checkpoint) and at 0.6 s (inside `discharge`, the gate's history placed at a start that
// only the checkpoint knows), continued to 0.9 s: bit for bit the uninterrupted run.
TEST(Phases, RestartAcrossPhaseBoundariesReproducesTheRun) {
    const std::string base = test_folder("phases_restart");
    const std::string file = phase_hopper("phases_restart");
    ASSERT_EQ(run_to(file, base + "_whole", "0.9 s").exit_code, 0);
    ASSERT_EQ(run_to(file, base + "_split", "0.3 s").exit_code, 0);
    const std::string checkpoint = " --restart '" + base + "_split/checkpoint.bin'";
    for (const char* end : {"0.6 s", "0.9 s"}) {
        const auto next = run_cli("run '" + file + "' --set 'case.end_time=" + end + "' --out '" +
                                      base + "_split'" + checkpoint,
                                  base + "_split.log");
        ASSERT_EQ(next.exit_code, 0) << next.output;
    }
    const std::string a = read_file(base + "_whole/summary.json");
    const std::string b = read_file(base + "_split/summary.json");
    for (const char* figure : kFigures) {
        EXPECT_EQ(result_value(a, figure), result_value(b, figure)) << figure;
    }
    for (const char* name : {"hold", "settle", "discharge"}) {
        const auto whole = phase_record(a, name);
        const auto split = phase_record(b, name);
        ASSERT_FALSE(whole.empty() || split.empty());
        EXPECT_TRUE(whole == split) << name << ": " << whole.end << " against " << split.end;
    }
}

// The two conditions in sequence on the CI closure hopper
// (cases/hopper_discharge/hopper_closure_small.toml): `settle` ends when the fill settles and
// removes the gate (remove_at = "phase:discharge"), `discharge` ends once the sink has taken
// 20 kg/m, and the closer slides in from the start of `closed` (its history counted from
// there). The sink's own discharge.csv places the end independently: every output instant
// before it shows less than 20 kg/m, every one from it on at least that (the phase ends with
// the first step whose total reaches it); and the closer covers the orifice 0.1 s after that
// start, so the outflow ends: what leaves in the last 0.2 s of the run (the closer shut 0.3 s
// before) is nothing. Measured: settled at 0.404 s, 21 kg/m out at 0.702 s (particles of
// 0.75 kg/m), the closer across the orifice at 0.812 s, 36 kg/m out from 0.9 s on.
TEST(Phases, DischargedMassEndsAPhaseAndTheCloserFollows) {
    const std::string file = test_folder("phases_close") + ".toml";
    std::string text = read_file(source_path("cases/hopper_discharge/hopper_closure_small.toml"));
    text = std::regex_replace(text, std::regex("remove_at = \"0.4 s\"[^\n]*\n"),
                              "remove_at = \"phase:discharge\"\n");
    const std::string closer =
        R"(velocity_history = [["0 s", "0 0 m/s"], ["1.2 s", "0 0 m/s"], ["1.205 s", "-5 0 m/s"],
                    ["1.305 s", "-5 0 m/s"], ["1.31 s", "0 0 m/s"], ["10 s", "0 0 m/s"]])";
    const auto at = text.find(closer);
    ASSERT_NE(at, std::string::npos) << "the closure case's closer history changed";
    text.replace(at, closer.size(),
                 R"(history_start = "phase:closed"
velocity_history = [["0 s", "0 0 m/s"], ["0.005 s", "-5 0 m/s"], ["0.105 s", "-5 0 m/s"],
                    ["0.11 s", "0 0 m/s"]])");
    std::ofstream(file) << text << R"(
[[phase]]
name = "settle"
end = "settled"
kinetic_energy_fraction = 1e-3

[[phase]]
name = "discharge"
end = "discharged"
discharged_mass = "20 kg/m"

[[phase]]
name = "closed"
)";
    const std::string out = test_folder("phases_close");
    const auto run = run_to(file, out, "1.5 s");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const std::string summary = read_file(out + "/summary.json");
    const PhaseText discharge = phase_record(summary, "discharge");
    const PhaseText closed = phase_record(summary, "closed");
    ASSERT_FALSE(discharge.empty() || closed.empty());
    EXPECT_EQ(discharge.ended_by, "\"discharged\"");
    EXPECT_EQ(closed.start, discharge.end);
    EXPECT_EQ(result_value(summary, "wall_gate_force_y"), 0.0) << "the gate left";
    const double end = std::stod(discharge.end);
    constexpr double kMass = 20.0; // kg/m
    const auto rows = discharge_rows(out);
    double last = 0.0;
    for (const auto& [time, mass] : rows) {
        EXPECT_EQ(mass >= kMass, time >= end) << "t = " << time << " s: " << mass << " kg/m";
        if (time <= 1.3 + 1e-9) {
            last = mass;
        }
    }
    ASSERT_LT(end + 0.11, 1.3) << "the closer shuts before the last 0.2 s";
    EXPECT_EQ(rows.back().second, last) << "nothing left after the closure";
}

} // namespace
} // namespace grainload::testing
