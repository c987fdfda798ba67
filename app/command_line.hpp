#pragma once

#include <optional>
#include <string>
#include <vector>

namespace grainload::app {

/// What the user asked for on the command line.
struct CommandLine {
    enum class Command { run, check, matpoint, version, help };
    Command command = Command::help;
    std::string input;                  ///< CASE.toml or DRIVER.toml
    std::optional<std::string> out;     ///< --out
    std::optional<int> threads;         ///< --threads
    std::vector<std::string> overrides; ///< --set key=value, in order
    std::optional<std::string> restart; ///< --restart CHECKPOINT
};

/// Parse argv; throws io::CaseError (exit code 2) on a malformed command line.
CommandLine parse_command_line(int argc, const char* const* argv);

/// The --help text.
const char* usage();

} // namespace grainload::app
