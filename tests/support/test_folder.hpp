#pragma once
// Each test process's own output folder, and the removal of ended ones.

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>

namespace grainload::testing {

/// Whether `folder_name` is grainload_<process id> of a process that has ended.
inline bool names_an_ended_process(const std::string& folder_name) {
    const std::string prefix = "grainload_";
    const std::string pid = folder_name.substr(std::min(prefix.size(), folder_name.size()));
    const bool digits =
        !pid.empty() && pid.size() < 10 &&
        std::all_of(pid.begin(), pid.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
    return folder_name.starts_with(prefix) && digits &&
           ::kill(static_cast<pid_t>(std::stol(pid)), 0) != 0 && errno == ESRCH;
}

/// This test process's own folder, TempDir()/grainload_<process id>/: two suites that run at
/// once (two worktrees' test runs, which share /tmp, or a test binary run by hand beside ctest)
/// never write into each other's output folders. Made on first use, when the folders of processes
/// that have ended are removed, so that they do not pile up (a failed run's output stays until
/// then).
inline const std::string& process_folder() {
    static const std::string folder = [] {
        std::error_code ignored; // another process may be removing the same folder
        for (const auto& entry : std::filesystem::directory_iterator(::testing::TempDir())) {
            if (names_an_ended_process(entry.path().filename().string())) {
                std::filesystem::remove_all(entry.path(), ignored);
            }
        }
        const std::string own =
            ::testing::TempDir() + "grainload_" + std::to_string(::getpid()) + "/";
        std::filesystem::create_directories(own);
        return own;
    }();
    return folder;
}

/// The path process_folder()/<name> for a test's output (a test that may find a stale frame of
/// an earlier run there removes it first); the caller adds suffixes (`_whole`, `.log`).
inline std::string test_folder(const std::string& name) {
    return process_folder() + name;
}

} // namespace grainload::testing
