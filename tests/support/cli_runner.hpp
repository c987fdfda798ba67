#pragma once
// The grainload executable run as a user runs it, and its output.

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace grainload::testing {

/// Result of running the grainload executable the way a user does.
struct CliResult {
    int exit_code = -1;
    std::string output; ///< stdout and stderr together
};

inline std::string source_path(const std::string& relative) {
    return std::string(GRAINLOAD_SOURCE_DIR) + "/" + relative;
}

/// Run `grainload <arguments>` (arguments already shell-quoted by the caller).
inline CliResult run_cli(const std::string& arguments, const std::string& log_file) {
    const std::string command =
        std::string(GRAINLOAD_EXECUTABLE) + " " + arguments + " > " + log_file + " 2>&1";
    const int status = std::system(command.c_str());
    CliResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(log_file);
    std::ostringstream text;
    text << in.rdbuf();
    result.output = text.str();
    return result;
}

inline std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace grainload::testing
