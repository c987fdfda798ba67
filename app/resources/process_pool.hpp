#pragma once
// Child processes run at most a given number at a time (posix_spawn), output to files.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace grainload::app {

/// How a child process ended.
struct ProcessResult {
    int exit_code = -1; ///< -1 when it ended by a signal or could not be started
    int signal = 0;     ///< the signal that ended it, 0 otherwise
    double elapsed_s = 0.0;
};

/// One command: argv (argv[0] a path, not searched in PATH) and the file that receives its
/// stdout and stderr.
struct ProcessSpec {
    std::vector<std::string> argv;
    std::string log_file;
};

/// Runs the commands with at most `jobs` at a time (posix_spawn), in order, and calls
/// `on_done(index, result)` as each ends. Returns when all have ended.
void run_processes(const std::vector<ProcessSpec>& commands, int jobs,
                   const std::function<void(std::size_t, const ProcessResult&)>& on_done);

/// Runs one command and waits for it.
ProcessResult run_process(const ProcessSpec& command);

} // namespace grainload::app
