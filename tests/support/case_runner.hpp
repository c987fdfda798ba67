#pragma once

#include "support/cli_runner.hpp"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <regex>
#include <string>

namespace grainload::testing {

/// A case run through the CLI and the folder it wrote.
struct CaseRun {
    CliResult cli;
    std::string out; ///< output folder; its log is out + ".log"
};

/// Runs `grainload run <source dir>/<case_file> --out <folder> <options>` the way a user does,
/// into a fresh folder TempDir()/grainload_<name> (a stale frame from an earlier run must not
/// be read as this run's). `options` are appended as written (already shell-quoted).
inline CaseRun run_case_file(const std::string& case_file, const std::string& name,
                             const std::string& options = "") {
    CaseRun run;
    run.out = ::testing::TempDir() + "grainload_" + name;
    std::filesystem::remove_all(run.out);
    run.cli = run_cli("run '" + source_path(case_file) + "' --out '" + run.out + "' " + options,
                      run.out + ".log");
    return run;
}

/// The value of result `name` in a summary.json text. A result that is missing or written as
/// null (an angle that cannot be fitted, a rest not reached) fails the test and reads as NaN.
inline double result_value(const std::string& summary, const std::string& name) {
    const std::regex pattern("\"" + name + "\": \\{\"value\": ([-+0-9.eE]+)");
    std::smatch match;
    EXPECT_TRUE(std::regex_search(summary, match, pattern)) << name << " missing or null";
    return match.empty() ? std::nan("") : std::stod(match[1]);
}

} // namespace grainload::testing
