#pragma once
// Runs killed with SIGKILL and restarted, compared with the run left alone.

// Runs of the CLI killed with SIGKILL and restarted, and the comparison of everything a run
// writes with what the uninterrupted run wrote.

#include "support/cli_runner.hpp"
#include "support/test_folder.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <gtest/gtest.h>
#include <random>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace grainload::testing {

inline std::string quoted(const std::vector<std::string>& arguments) {
    std::string line;
    for (const auto& a : arguments) {
        line += " '" + a + "'";
    }
    return line;
}

inline std::string fresh_directory(const std::string& name) {
    const std::string directory = test_folder(name);
    std::filesystem::remove_all(directory);
    return directory;
}

/// Starts the CLI with `arguments` and `--out out`, its output going to out.log.
inline pid_t start_cli(const std::vector<std::string>& arguments, const std::string& out) {
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
        if (pin_blas_kernels()) {
            setenv("OPENBLAS_CORETYPE", kPinnedBlasKernels, 1);
        }
        execv(GRAINLOAD_EXECUTABLE, argv.data());
        _exit(127);
    }
    return pid;
}

/// The lines of `text` for which `keep` holds, each with its '\n'.
template <class Keep> std::string kept_lines(const std::string& text, Keep keep) {
    std::string kept;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (keep(line)) {
            kept += line + '\n';
        }
    }
    return kept;
}

/// The lines of summary.json that a restart must reproduce: steps, simulated time, results
/// (not the wall time, the speed, the threads, or the estimate, which a restart does not make).
inline std::string reproducible_summary(const std::string& path) {
    return kept_lines(read_file(path), [](const std::string& line) {
        for (const char* varies : {"wall_time", "cpu_time", "per_second", "\"threads\"",
                                   "case_file", "fem_factorisations", "fem_back_substitutions"}) {
            if (line.find(varies) != std::string::npos) {
                return false;
            }
        }
        return true;
    });
}

/// log.txt without what depends on the machine's speed or the process (the progress lines, the
/// start and end lines, the restart's own line): the events and hints, each once.
inline std::string log_events(const std::string& path) {
    return kept_lines(read_file(path), [](const std::string& line) {
        for (const char* varies :
             {"t = ", "grainload ", "restarted from ", "done: ", "estimate before the run"}) {
            if (line.starts_with(varies)) {
                return false;
            }
        }
        return true;
    });
}

/// coupling.csv without its last three columns, the wall-clock seconds of each window.
inline std::string coupling_without_seconds(const std::string& path) {
    std::string kept;
    std::istringstream in(read_file(path));
    for (std::string line; std::getline(in, line);) {
        std::size_t cut = line.size();
        for (int k = 0; k < 3 && cut != std::string::npos; ++k) {
            cut = line.rfind(',', cut - 1);
        }
        kept += line.substr(0, cut) + '\n';
    }
    return kept;
}

/// A checkpoint file's state: its bytes less the marks of the streamed files (which record the
/// log's length, set by the wall clock) and less the trailer (whose hash covers the marks).
/// The layout (app/checkpoint.cpp): magic, time, step, the frame times (a count and as many
/// doubles), the marks (a count, then each a name as a count and bytes, a length and a hash),
/// the modules' states, the trailer of 16 bytes.
inline std::string checkpoint_state(const std::string& file) {
    auto count_at = [&](std::size_t at) {
        std::uint64_t count = 0;
        if (at + sizeof count <= file.size()) {
            std::memcpy(&count, file.data() + at, sizeof count);
        }
        return static_cast<std::size_t>(count);
    };
    const std::size_t marks = 32 + 8 * count_at(24);
    std::size_t end = marks + 8;
    for (std::size_t k = count_at(marks); k > 0 && end < file.size(); --k) {
        end += 8 + count_at(end) + 16;
    }
    if (end + 16 > file.size()) {
        ADD_FAILURE() << "not a checkpoint's layout";
        return {};
    }
    return file.substr(0, marks) + file.substr(end, file.size() - 16 - end);
}

/// Every file a run wrote under `out`, by relative path: the frames, the collection, the
/// streamed tables and logs, the wall maps, the summary; not the checkpoint (compared by its
/// state) nor a stale .tmp a kill left.
inline std::vector<std::string> output_files(const std::string& out) {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(out)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_regular_file() && entry.path().extension() != ".tmp" &&
            name != "checkpoint.bin") {
            files.push_back(std::filesystem::relative(entry.path(), out).string());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

/// Every output file of `restarted` equals the uninterrupted run's in `whole`: byte for byte,
/// but for what the wall clock writes (summary.json's speed, log.txt's progress lines,
/// coupling.csv's seconds per window); and the last checkpoint holds the same state.
inline void expect_same_outputs(const std::string& whole, const std::string& restarted,
                                const std::string& what) {
    EXPECT_TRUE(checkpoint_state(read_file(whole + "/checkpoint.bin")) ==
                checkpoint_state(read_file(restarted + "/checkpoint.bin")))
        << what << ": the last checkpoints' states differ";
    const auto files = output_files(whole);
    ASSERT_EQ(files, output_files(restarted)) << what;
    for (const std::string& file : files) {
        const std::string a = whole + "/" + file;
        const std::string b = restarted + "/" + file;
        if (file == "summary.json") {
            EXPECT_EQ(reproducible_summary(a), reproducible_summary(b)) << what;
        } else if (file == "log.txt") {
            EXPECT_EQ(log_events(a), log_events(b)) << what;
        } else if (file == "coupling.csv") {
            EXPECT_EQ(coupling_without_seconds(a), coupling_without_seconds(b)) << what;
        } else {
            EXPECT_TRUE(read_file(a) == read_file(b)) << what << ": " << file << " differs";
        }
    }
}

/// Every table and log a killed run left ends with a whole line.
inline void expect_whole_lines(const std::string& out, const std::string& what) {
    for (const std::string& file : output_files(out)) {
        if (file.ends_with(".csv") || file.ends_with(".txt")) {
            const std::string text = read_file(out + "/" + file);
            EXPECT_TRUE(text.empty() || text.back() == '\n')
                << what << ": " << file << " ends in a torn line";
        }
    }
}

/// Runs `arguments` into `out` and kills it with SIGKILL `delay` seconds after its first
/// checkpoint appeared; true if the kill came before the run ended.
inline bool run_and_kill(const std::vector<std::string>& arguments, const std::string& out,
                         double delay) {
    const pid_t pid = start_cli(arguments, out);
    EXPECT_GT(pid, 0);
    int status = 0;
    while (!std::filesystem::exists(out + "/checkpoint.bin")) {
        if (waitpid(pid, &status, WNOHANG) == pid) {
            ADD_FAILURE() << "the run ended before its first checkpoint:\n"
                          << read_file(out + ".log");
            return false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
}

/// The uninterrupted run of `arguments`, then `seeds` runs killed at pseudo-random moments
/// (drawn anew each time and printed) and restarted from the checkpoint each left: every output
/// file must equal the uninterrupted run's, and the killed run's tables end in whole lines.
inline void expect_restarts_reproduce_the_run(const std::vector<std::string>& arguments,
                                              const std::string& name, int seeds) {
    const std::string whole = fresh_directory(name + "_whole");
    const auto start = std::chrono::steady_clock::now();
    const auto reference = run_cli(quoted(arguments) + " --out '" + whole + "'", whole + ".log");
    ASSERT_EQ(reference.exit_code, 0) << reference.output;
    const double duration =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const unsigned seed = std::random_device{}();
    std::mt19937 engine(seed);
    for (int k = 0; k < seeds; ++k) {
        const std::string killed = fresh_directory(name + "_killed_" + std::to_string(k));
        const double delay = std::uniform_real_distribution<double>(0.0, 0.8 * duration)(engine);
        const bool was_killed = run_and_kill(arguments, killed, delay);
        std::ostringstream what;
        what << name << ", seed " << seed << ", kill " << k << ": SIGKILL " << delay
             << " s after the first checkpoint of a " << duration << " s run";
        std::cout << what.str() << (was_killed ? "" : " (it had finished)") << "\n";
        expect_whole_lines(killed, what.str());
        const auto restarted = run_cli(quoted(arguments) + " --out '" + killed + "' --restart '" +
                                           killed + "/checkpoint.bin'",
                                       killed + ".restart.log");
        ASSERT_EQ(restarted.exit_code, 0) << what.str() << "\n" << restarted.output;
        expect_same_outputs(whole, killed, what.str());
    }
    // A kill that lands after the run ended leaves its last checkpoint: a restart from it takes
    // no step, and must still report what the run did (a coupled shell's support reactions
    // once came back as zero, its sand loads not restored).
    const std::string finished = fresh_directory(name + "_finished");
    std::filesystem::copy(whole, finished, std::filesystem::copy_options::recursive);
    const auto again = run_cli(quoted(arguments) + " --out '" + finished + "' --restart '" +
                                   finished + "/checkpoint.bin'",
                               finished + ".restart.log");
    ASSERT_EQ(again.exit_code, 0) << name << ", restarted after its end\n" << again.output;
    expect_same_outputs(whole, finished, name + ", restarted from its last checkpoint");
}

} // namespace grainload::testing
