#pragma once
// The grainload command line: its commands, their options and their usage texts.

#include <optional>
#include <string>
#include <vector>

namespace grainload::app {

/// What the user asked for on the command line.
struct CommandLine {
    enum class Command { run, check, matpoint, trade, version, help };
    Command command = Command::help;
    std::string input;              ///< CASE.toml or DRIVER.toml
    std::optional<std::string> out; ///< --out
    std::optional<int> threads;     ///< --threads N
    /// --threads auto: the cores other work leaves free at start (app/resources/thread_count.hpp).
    bool auto_threads = false;
    std::vector<std::string> overrides; ///< --set key=value, in order
    std::optional<std::string> restart; ///< --restart CHECKPOINT
    /// For help: the command whose usage to print ("run"); empty for the overview.
    std::string help_topic;
    /// For `help keys TABLE`: the table whose keys to print; empty: every table's name.
    std::string help_table;
};

/// Parse argv; throws io::CaseError (exit code 2) on a malformed command line. `--help` or
/// `-h` anywhere, `grainload help` and `grainload help COMMAND` ask for help (exit code 0).
CommandLine parse_command_line(int argc, const char* const* argv);

/// The usage overview (`grainload --help`).
const char* usage();

/// The usage of one command ("run", "check", "matpoint", "version", "help"); throws io::CaseError
/// for an unknown one.
std::string usage(const std::string& command);

} // namespace grainload::app
