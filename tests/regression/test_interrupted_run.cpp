// A run killed with SIGKILL and restarted from its checkpoint, and restarts from checkpoints
// that are truncated, corrupted or of another case (issue 18, section 6).

#include "support/case_runner.hpp"
#include "support/cli_runner.hpp"
#include "support/test_folder.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <random>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
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

std::string quoted(const std::vector<std::string>& arguments) {
    std::string line;
    for (const auto& a : arguments) {
        line += " '" + a + "'";
    }
    return line;
}

std::string fresh_directory(const std::string& name) {
    const std::string directory = test_folder(name);
    fs::remove_all(directory);
    return directory;
}

/// Starts the CLI with `arguments` and `--out out`, its output going to out.log.
pid_t start_cli(const std::vector<std::string>& arguments, const std::string& out) {
    std::vector<std::string> all = arguments;
    all.insert(all.end(), {"--out", out});
    const std::string log = out + ".log";
    const pid_t pid = fork();
    if (pid == 0) {
        std::freopen(log.c_str(), "w", stdout);
        std::freopen(log.c_str(), "a", stderr);
        std::vector<char*> argv{const_cast<char*>(GRAINLOAD_EXECUTABLE)};
        for (auto& a : all) {
            argv.push_back(a.data());
        }
        argv.push_back(nullptr);
        execv(GRAINLOAD_EXECUTABLE, argv.data());
        _exit(127);
    }
    return pid;
}

/// The lines of summary.json that a restart must reproduce: steps, simulated time, results
/// (not the wall time, the speed or the threads).
std::string reproducible_summary(const std::string& path) {
    const std::string text = read_file(path);
    std::string kept;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        const std::string line = text.substr(start, end - start);
        if (line.find("wall_time") == std::string::npos &&
            line.find("cpu_time") == std::string::npos &&
            line.find("per_second") == std::string::npos &&
            line.find("\"threads\"") == std::string::npos &&
            line.find("case_file") == std::string::npos) {
            kept += line + '\n';
        }
        start = end == std::string::npos ? text.size() : end + 1;
    }
    return kept;
}

/// Every frame file (.vtm and the pieces) and the collection, by relative path.
std::vector<std::string> frame_files(const std::string& out) {
    std::vector<std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(out + "/frames")) {
        if (entry.is_regular_file() && entry.path().extension() != ".tmp") {
            files.push_back(fs::relative(entry.path(), out).string());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

// SIGKILL at a pseudo-random moment after the first checkpoint (the delay drawn anew each run
// and printed), then a restart from whatever checkpoint the killed run left: every frame file
// and the summary's figures must equal the uninterrupted run's byte for byte. The restart
// reproduces a run bit for bit (RestartOfADeformingRunReproducesTheUninterruptedRun), and the
// atomic writes (write, then rename) mean the kill can leave a stale .tmp but never a partial
// checkpoint, frame or collection.
TEST(InterruptedRun, KilledAtARandomMomentAndRestartedReproducesTheUninterruptedRun) {
    const std::string whole = fresh_directory("whole_run");
    const auto start = std::chrono::steady_clock::now();
    const auto reference =
        run_cli(quoted(kRunArguments) + " --out '" + whole + "'", whole + ".log");
    ASSERT_EQ(reference.exit_code, 0) << reference.output;
    const double duration =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const std::string killed = fresh_directory("killed_run");
    const unsigned seed = std::random_device{}();
    std::mt19937 engine(seed);
    const double delay = std::uniform_real_distribution<double>(0.0, 0.8 * duration)(engine);
    const pid_t pid = start_cli(kRunArguments, killed);
    ASSERT_GT(pid, 0);
    while (!fs::exists(killed + "/checkpoint.bin")) {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    const bool was_killed = WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
    std::cout << "seed " << seed << ": SIGKILL " << delay << " s after the first checkpoint of a "
              << duration << " s run; " << (was_killed ? "killed" : "it had finished") << "\n";
    const auto restarted = run_cli(quoted(kRunArguments) + " --out '" + killed + "' --restart '" +
                                       killed + "/checkpoint.bin'",
                                   killed + ".restart.log");
    ASSERT_EQ(restarted.exit_code, 0) << restarted.output;

    const auto files = frame_files(whole);
    ASSERT_EQ(files, frame_files(killed));
    ASSERT_EQ(std::count_if(files.begin(), files.end(),
                            [](const std::string& f) { return f.ends_with(".vtm"); }),
              31); // 0 to 0.3 s every 10 ms
    for (const std::string& file : files) {
        EXPECT_EQ(read_file(whole + "/" + file), read_file(killed + "/" + file)) << file;
    }
    EXPECT_EQ(read_file(whole + "/column_collapse_2d_small.pvd"),
              read_file(killed + "/column_collapse_2d_small.pvd"));
    EXPECT_EQ(reproducible_summary(whole + "/summary.json"),
              reproducible_summary(killed + "/summary.json"));
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
