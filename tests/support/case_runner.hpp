#pragma once
// Shipped cases run through the CLI, and the figures of their summary.json.

#include "support/cli_runner.hpp"
#include "support/test_folder.hpp"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <regex>
#include <string>
#include <vector>

namespace grainload::testing {

/// A case run through the CLI and the folder it wrote.
struct CaseRun {
    CliResult cli;
    std::string out; ///< output folder; its log is out + ".log"
};

/// Runs `grainload run <source dir>/<case_file> --out <folder> <options>` the way a user does,
/// into a fresh folder test_folder(name). `options` are appended as written (already
/// shell-quoted).
inline CaseRun run_case_file(const std::string& case_file, const std::string& name,
                             const std::string& options = "") {
    CaseRun run;
    run.out = test_folder(name);
    std::filesystem::remove_all(run.out);
    run.cli = run_cli("run '" + source_path(case_file) + "' --out '" + run.out + "' " + options,
                      run.out + ".log");
    return run;
}

/// Runs a case that meshes a Gmsh geometry: the case file and the files it reads (`files`,
/// in the source tree's `folder`, the case file first) are copied to a fresh folder
/// test_folder(name), so that the mesh Gmsh makes lands there and not in the source tree, and
/// the copy is run into its `out` subfolder.
inline CaseRun run_case_copy(const std::string& folder, const std::vector<std::string>& files,
                             const std::string& name) {
    const std::string dir = test_folder(name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    for (const std::string& file : files) {
        std::filesystem::copy_file(source_path(folder + "/" + file), dir + "/" + file);
    }
    CaseRun run;
    run.out = dir + "/out";
    run.cli = run_cli("run '" + dir + "/" + files.front() + "' --out '" + run.out + "'",
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

/// What summary.json writes beside a figure that has a reference: the reference, its source and
/// the relative error |value - reference| / |reference|.
struct FigureReference {
    double value = std::nan("");
    double reference = std::nan("");
    double relative_error = std::nan("");
    std::string source;
};

/// The reference of result `name` in a summary.json text; a figure without one (or without a
/// relative error: a reference of 0) fails the test and reads as NaN.
inline FigureReference figure_reference(const std::string& summary, const std::string& name) {
    const std::regex pattern("\"" + name +
                             "\": \\{\"value\": ([-+0-9.eE]+), \"unit\": \"[^\"]*\", "
                             "\"reference\": ([-+0-9.eE]+), \"source\": \"([^\"]*)\", "
                             "\"relative_error\": ([-+0-9.eE]+)\\}");
    std::smatch match;
    EXPECT_TRUE(std::regex_search(summary, match, pattern)) << name << ": no reference";
    FigureReference figure;
    if (!match.empty()) {
        figure = {std::stod(match[1]), std::stod(match[2]), std::stod(match[4]), match[3]};
    }
    return figure;
}

/// The books of a CI discharge run: the mass audit closes to the round-off of sums of at most
/// `masses` equal particle masses (masses x eps of the total), and the energy books within
/// 0.3 %, the bound the CI cases keep (docs/user-guide/sph.md).
inline void expect_books_close(const std::string& summary, int masses) {
    EXPECT_LT(std::abs(result_value(summary, "mass_audit_error")), masses * 2.2e-16);
    constexpr double kEnergyBooks = 3e-3;
    EXPECT_LT(std::abs(result_value(summary, "energy_balance_error")), kEnergyBooks);
}

/// A top-level number of a summary.json text ("wall_time_s", "material_points", ...).
inline double summary_number(const std::string& summary, const std::string& name) {
    const std::regex pattern("\"" + name + "\": ([-+0-9.eE]+)");
    std::smatch match;
    EXPECT_TRUE(std::regex_search(summary, match, pattern)) << name << " missing";
    return match.empty() ? std::nan("") : std::stod(match[1]);
}

/// The restart check's two runs of `case_file`: to `end_time` in one go into `<base>_whole`, and
/// stopped at `stop_time`, then continued from its checkpoint to `end_time`, into `<base>_split`.
/// Returns the output of the first run that failed, empty when all three exited with 0.
inline std::string run_whole_and_split(const std::string& case_file, const std::string& base,
                                       const std::string& stop_time, const std::string& end_time) {
    const std::string kase = "'" + source_path(case_file) + "'";
    const std::string to_end = " --set 'case.end_time=" + end_time + "'";
    std::filesystem::remove_all(base + "_whole");
    std::filesystem::remove_all(base + "_split");
    for (const auto& [options, log] :
         {std::pair{to_end + " --out '" + base + "_whole'", base + "_whole.log"},
          std::pair{" --set 'case.end_time=" + stop_time + "' --out '" + base + "_split'",
                    base + "_first.log"},
          std::pair{to_end + " --out '" + base + "_split' --restart '" + base +
                        "_split/checkpoint.bin'",
                    base + "_second.log"}}) {
        const auto run = run_cli("run " + kase + options, log);
        if (run.exit_code != 0) {
            return run.output.empty() ? "exit code " + std::to_string(run.exit_code) : run.output;
        }
    }
    return "";
}

} // namespace grainload::testing
