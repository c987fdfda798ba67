// A DEM scene run through its phases from the command line: beads rained in until a stated
// time, left to settle, then their container removed when the next phase begins; the heap's
// centre of mass falls freely from there, and a run killed and restarted across the phases'
// ends writes what the uninterrupted run writes.

#include "support/case_runner.hpp"
#include "support/gold_summary.hpp"
#include "support/interrupted_run.hpp"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <regex>
#include <string>

namespace {

using namespace grainload::testing;

constexpr const char* kCase = "cases/grain_phases/grain_phases_small.toml";
constexpr double kGravity = 9.81; // the case's gravity, the default [case] gravity

/// summary.json's record of phase `name`: start and end in seconds (NaN where null) and what
/// ended it.
struct PhaseRecord {
    double start = std::nan("");
    double end = std::nan("");
    std::string ended_by;
};

double number_or_nan(const std::string& text) {
    return text == "null" ? std::nan("") : std::stod(text);
}

PhaseRecord phase_record(const std::string& summary, const std::string& name) {
    const std::regex pattern("\\{\"name\": \"" + name +
                             "\", \"start\": ([^,]+), \"end\": ([^,]+), \"ended_by\": ([^}]+)\\}");
    std::smatch match;
    EXPECT_TRUE(std::regex_search(summary, match, pattern)) << name << "\n" << summary;
    if (match.empty()) {
        return {};
    }
    return {number_or_nan(match[1]), number_or_nan(match[2]), match[3]};
}

std::string seconds(double t) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g s", t);
    return text;
}

// The phases end as the case states: "rain" at its stated 0.35 s, "settle" when the beads'
// kinetic energy fell below 1e-3 of its peak, "drop" when the sink took its first gram; each
// next phase begins where the one before ended, and all five walls leave with the step that
// began "drop". The source, whose end names "settle", made rate x 0.35 s = 140 beads (its
// running sum over some 57 000 steps may fall short of the last by round-off: one bead).
// Then the free fall: from the end of "settle" no wall touches a bead and the contact forces
// between beads cancel in pairs, so the centre of mass moves by v0 tau - g tau^2 / 2 over the
// next tau = 0.1 s, v0 its velocity when the walls left. The run to that instant and the run
// to the end of "settle" give the two heights; |v0| is at most the beads' rms speed then,
// sqrt(2 E_kin / m), which bounds the difference from g tau^2 / 2: 1.5e-3 m of 0.049 m
// (measured 4.0e-6 m: the heap's centre of mass was near rest).
TEST(GrainPhasesSmall, TheContainerLeavesWhenTheHeapSettledAndTheHeapFallsFreely) {
    // One thread: the DEM's many short parallel loops gain nothing on 150 beads.
    const CaseRun run = run_case_file(kCase, "grain_phases_small", "--threads 1");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    const PhaseRecord rain = phase_record(summary, "rain");
    const PhaseRecord settle = phase_record(summary, "settle");
    const PhaseRecord drop = phase_record(summary, "drop");
    const PhaseRecord fall = phase_record(summary, "fall");
    EXPECT_EQ(rain.end, 0.35);
    EXPECT_EQ(rain.ended_by, "\"time\"");
    EXPECT_EQ(settle.start, rain.end);
    EXPECT_EQ(settle.ended_by, "\"settled\"");
    EXPECT_EQ(drop.start, settle.end);
    EXPECT_EQ(drop.ended_by, "\"discharged\"");
    EXPECT_EQ(fall.start, drop.end);
    EXPECT_TRUE(std::isnan(fall.end));
    const std::string log = read_file(run.out + "/log.txt");
    char removal[96];
    std::snprintf(removal, sizeof removal, "removed at t = %g s", settle.end);
    for (const char* wall : {"side_x0", "side_x1", "side_y0", "side_y1", "floor"}) {
        EXPECT_NE(log.find("wall " + std::string(wall) + " " + removal), std::string::npos)
            << wall << "\n"
            << log;
    }
    EXPECT_NEAR(result_value(summary, "source_feed_created"), 140.0, 1.0);
    EXPECT_LT(std::abs(result_value(summary, "mass_audit_error")), 1e-12);
    expect_matches_gold(run.out, kCase);

    const double tau = 0.1;
    const CaseRun at_rest =
        run_case_file(kCase, "grain_phases_small_rest",
                      "--threads 1 --set 'case.end_time=" + seconds(settle.end) + "'");
    const CaseRun falling =
        run_case_file(kCase, "grain_phases_small_fall",
                      "--threads 1 --set 'case.end_time=" + seconds(settle.end + tau) + "'");
    ASSERT_EQ(at_rest.cli.exit_code, 0) << at_rest.cli.output;
    ASSERT_EQ(falling.cli.exit_code, 0) << falling.cli.output;
    const std::string rest_summary = read_file(at_rest.out + "/summary.json");
    const std::string fall_summary = read_file(falling.out + "/summary.json");
    EXPECT_EQ(phase_record(rest_summary, "settle").end, settle.end);
    const double drop_height = result_value(rest_summary, "grains_centre_of_mass_z") -
                               result_value(fall_summary, "grains_centre_of_mass_z");
    const double rms_speed = std::sqrt(2.0 * result_value(rest_summary, "kinetic_energy") /
                                       result_value(rest_summary, "scene_mass"));
    EXPECT_NEAR(drop_height, 0.5 * kGravity * tau * tau, rms_speed * tau);
}

// SIGKILL at random moments, across the ends of "rain" and "settle", and a restart: frames,
// wall_forces.csv, discharge.csv, the log and summary equal the uninterrupted run's (the
// phases' state is a scene part of the checkpoint, and the walls' removal times follow it).
TEST(GrainPhasesSmall, KilledAndRestartedAcrossPhasesReproducesTheUninterruptedRun) {
    const std::vector<std::string> arguments = {
        "run",   source_path(kCase),           "--set",     "case.end_time=0.6 s",
        "--set", "case.output_interval=20 ms", "--threads", "1"};
    expect_restarts_reproduce_the_run(arguments, "grain_phases", 2);
}

} // namespace
