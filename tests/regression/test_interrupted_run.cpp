// A run killed with SIGKILL and restarted from its checkpoint, restarts that would lose or
// invent output (an end time before the checkpoint, streamed files that lost their history),
// and restarts from checkpoints that are truncated, corrupted or of another case.

#include "support/case_runner.hpp"
#include "support/cli_runner.hpp"
#include "support/interrupted_run.hpp"
#include "support/test_folder.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace {

using namespace grainload::testing;
namespace fs = std::filesystem;

// The plastic 2D column of the restart test in test_column_collapse_small.cpp, with kernel
// gradient correction and a frame (and checkpoint) every 10 ms to 0.3 s: 31 checkpoints, so
// the kill lands in the middle of most of what a run does (stepping, writing frames,
// replacing the checkpoint).
const std::vector<std::string> kRunArguments = {
    "run",       source_path("cases/column_collapse_2d/column_collapse_2d_small.toml"),
    "--set",     "sph.kernel_gradient_correction=true",
    "--set",     "case.end_time=0.3 s",
    "--set",     "case.output_interval=10 ms",
    "--threads", "1"};
constexpr const char* kLastFrame = "/frames/column_collapse_2d_small_000030.vtm";

// SIGKILL at pseudo-random moments after the first checkpoint (the delays drawn anew each run
// and printed), then a restart from whatever checkpoint the killed run left: every file the run
// writes (frames, collection, wall_forces.csv, log, summary) must equal the uninterrupted run's.
// The restart reproduces a run bit for bit (RestartOfADeformingRunReproducesTheUninterruptedRun);
// the atomic writes (write, then rename) mean the kill can leave a stale .tmp but never a
// partial checkpoint, frame or collection; the streamed tables are cut back to the checkpoint.
TEST(InterruptedRun, KilledAtARandomMomentAndRestartedReproducesTheUninterruptedRun) {
    expect_restarts_reproduce_the_run(kRunArguments, "column_2d", 2);
    const std::string whole = test_folder("column_2d_whole");
    EXPECT_TRUE(fs::exists(whole + kLastFrame));
    const auto files = output_files(whole);
    EXPECT_EQ(std::count_if(files.begin(), files.end(),
                            [](const std::string& f) { return f.ends_with(".vtm"); }),
              31); // 0 to 0.3 s every 10 ms
    // One row per wall and instant: 0 to 0.3 s every 10 ms, for the two walls of the container.
    const std::string forces = read_file(whole + "/wall_forces.csv");
    EXPECT_EQ(std::count(forces.begin(), forces.end(), '\n'), 1 + 31 * 2) << forces;
}

/// Runs the case to 0.05 s in `out` and returns its checkpoint's bytes.
std::string short_run(const std::string& out);

// A run restarted from the checkpoint of its last instant (the kill of the test above landing
// after the run had finished) takes no step; its summary must still report the figures the run
// ended with. It reported the walls' loads as 0 (they were sums formed in a step, not restored)
// and 7.5e8 particle-steps per second (the whole run's steps over the restart's 0.2 ms).
TEST(InterruptedRun, RestartedFromItsFinalCheckpointItReportsWhatTheRunEndedWith) {
    const std::string out = fresh_directory("finished_run");
    short_run(out);
    const std::string finished = reproducible_summary(out + "/summary.json");
    ASSERT_NE(finished.find("wall_floor_force_y"), std::string::npos) << finished;
    const auto restarted = run_cli(quoted(kRunArguments) + " --set 'case.end_time=0.05 s' --out '" +
                                       out + "' --restart '" + out + "/checkpoint.bin'",
                                   out + ".restart.log");
    ASSERT_EQ(restarted.exit_code, 0) << restarted.output;
    EXPECT_EQ(reproducible_summary(out + "/summary.json"), finished);
    // No step ran in the restarted process, so it moved no particle.
    EXPECT_EQ(summary_number(read_file(out + "/summary.json"), "particle_steps_per_second"), 0.0);
}

std::string short_run(const std::string& out) {
    const auto result = run_cli(
        quoted(kRunArguments) + " --set 'case.end_time=0.05 s' --out '" + out + "'", out + ".log");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return read_file(out + "/checkpoint.bin");
}

// A restart whose end time lies before the checkpoint's time has nothing to run and would
// leave no frame at its end time (it once "completed" and pointed at a .pvd frame that did not
// exist): refused with exit code 2, naming the key and both times, and nothing touched.
TEST(InterruptedRun, ARestartEndingBeforeItsCheckpointIsRefused) {
    const std::string out = fresh_directory("end_before_checkpoint");
    short_run(out);
    const auto before = output_files(out);
    const std::string log = read_file(out + "/log.txt");
    const std::string summary = read_file(out + "/summary.json");
    const auto result = run_cli(quoted(kRunArguments) + " --set 'case.end_time=0.03 s' --out '" +
                                    out + "' --restart '" + out + "/checkpoint.bin'",
                                out + ".early.log");
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("case.end_time"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("0.03 s lies before the time of the checkpoint"),
              std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("0.05 s"), std::string::npos) << result.output;
    EXPECT_EQ(output_files(out), before);
    EXPECT_EQ(read_file(out + "/log.txt"), log);
    EXPECT_EQ(read_file(out + "/summary.json"), summary);
}

// The streamed tables hold the run's history up to the checkpoint; a restart that does not find
// it (a table deleted or edited, a restart into another directory) would continue a table
// without its beginning: refused with exit code 2, naming the file, and no file touched.
TEST(InterruptedRun, ARestartThatWouldLoseAStreamedHistoryIsRefused) {
    const std::string out = fresh_directory("lost_history");
    short_run(out);
    const std::string forces = read_file(out + "/wall_forces.csv");
    const std::string log = read_file(out + "/log.txt");
    std::string edited = forces;
    edited[edited.size() / 2] = edited[edited.size() / 2] == '1' ? '2' : '1';
    std::ofstream(out + "/wall_forces.csv", std::ios::trunc) << edited;
    const std::string command = quoted(kRunArguments) + " --set 'case.end_time=0.1 s' --out '" +
                                out + "' --restart '" + out + "/checkpoint.bin'";
    const auto refused = run_cli(command, out + ".edited.log");
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_NE(refused.output.find("wall_forces.csv: the checkpoint was written after its first"),
              std::string::npos)
        << refused.output;
    EXPECT_EQ(read_file(out + "/wall_forces.csv"), edited);
    EXPECT_EQ(read_file(out + "/log.txt"), log);

    const std::string elsewhere = fresh_directory("lost_history_elsewhere");
    const auto moved = run_cli(quoted(kRunArguments) + " --set 'case.end_time=0.1 s' --out '" +
                                   elsewhere + "' --restart '" + out + "/checkpoint.bin'",
                               out + ".elsewhere.log");
    EXPECT_EQ(moved.exit_code, 2) << moved.output;
    EXPECT_NE(moved.output.find("is not in the output directory"), std::string::npos)
        << moved.output;

    // The table as the run left it: the restart continues it, and the whole run is reproduced.
    std::ofstream(out + "/wall_forces.csv", std::ios::trunc) << forces;
    const auto resumed = run_cli(command, out + ".resumed.log");
    ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
    const std::string whole = fresh_directory("lost_history_whole");
    ASSERT_EQ(run_cli(quoted(kRunArguments) + " --set 'case.end_time=0.1 s' --out '" + whole + "'",
                      whole + ".log")
                  .exit_code,
              0);
    EXPECT_EQ(read_file(out + "/wall_forces.csv"), read_file(whole + "/wall_forces.csv"));
}

void write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// A checkpoint that is truncated, has one flipped bit, is empty, is a directory or belongs to
// another case is refused with exit code 2 and a message naming the file, and the output it
// was to continue (frames, collection, summary) is left exactly as it was.
TEST(InterruptedRun, BadCheckpointsAreRefusedWithExitTwoAndTheOutputIsLeftAlone) {
    const std::string out = fresh_directory("bad_checkpoint");
    const std::string good = short_run(out);
    ASSERT_GT(good.size(), 1000u);
    std::string flipped = good;
    flipped[flipped.size() / 2] = static_cast<char>(flipped[flipped.size() / 2] ^ 0x10);
    const std::string other = fresh_directory("other_case");
    ASSERT_EQ(run_cli("run '" + source_path("cases/free_fall/free_fall_small.toml") + "' --out '" +
                          other + "'",
                      other + ".log")
                  .exit_code,
              0);
    struct Bad {
        const char* what;
        std::string bytes;
        const char* message;
    };
    const std::vector<Bad> cases = {
        {"truncated to half", good.substr(0, good.size() / 2), "checkpoint refused"},
        {"truncated by one byte", good.substr(0, good.size() - 1), "checkpoint refused"},
        {"one flipped bit", flipped, "checksum does not match"},
        {"empty", "", "too few for a checkpoint"},
        {"of another case", read_file(other + "/checkpoint.bin"), "the case makes"},
    };
    const std::string before_pvd = read_file(out + "/column_collapse_2d_small.pvd");
    const std::string before_summary = read_file(out + "/summary.json");
    const std::string before_frame = read_file(out + "/frames/column_collapse_2d_small_000005.vtm");
    const std::string bad = out + "/bad_checkpoint.bin";
    for (const Bad& c : cases) {
        write_bytes(bad, c.bytes);
        const auto result =
            run_cli(quoted(kRunArguments) + " --out '" + out + "' --restart '" + bad + "'",
                    out + ".bad.log");
        EXPECT_EQ(result.exit_code, 2) << c.what << "\n" << result.output;
        EXPECT_NE(result.output.find(bad + ": "), std::string::npos) << c.what << result.output;
        EXPECT_NE(result.output.find(c.message), std::string::npos) << c.what << result.output;
    }
    fs::remove(bad);
    fs::create_directory(bad);
    const auto directory = run_cli(
        quoted(kRunArguments) + " --out '" + out + "' --restart '" + bad + "'", out + ".bad.log");
    EXPECT_EQ(directory.exit_code, 2) << directory.output;
    EXPECT_NE(directory.output.find("is a directory"), std::string::npos) << directory.output;
    EXPECT_EQ(read_file(out + "/column_collapse_2d_small.pvd"), before_pvd);
    EXPECT_EQ(read_file(out + "/summary.json"), before_summary);
    EXPECT_EQ(read_file(out + "/frames/column_collapse_2d_small_000005.vtm"), before_frame);
    EXPECT_EQ(read_file(out + "/checkpoint.bin"), good);
}

} // namespace
