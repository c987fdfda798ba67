#include "app/resources/process_pool.hpp"

#include <cerrno>
#include <chrono>
#include <fcntl.h>
#include <map>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace grainload::app {

namespace {

using Clock = std::chrono::steady_clock;

/// Starts `spec`; returns its pid, or -1 when it could not be started.
pid_t start(const ProcessSpec& spec) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, spec.log_file.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    std::vector<char*> argv;
    for (const std::string& arg : spec.argv) {
        argv.push_back(const_cast<char*>(arg.c_str()));
    }
    argv.push_back(nullptr);
    pid_t pid = -1;
    const int error = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    return error == 0 ? pid : -1;
}

ProcessResult result_of(int status, Clock::time_point started) {
    ProcessResult r;
    r.elapsed_s = std::chrono::duration<double>(Clock::now() - started).count();
    if (WIFEXITED(status)) {
        r.exit_code = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        r.signal = WTERMSIG(status);
    }
    return r;
}

} // namespace

void run_processes(const std::vector<ProcessSpec>& commands, int jobs,
                   const std::function<void(std::size_t, const ProcessResult&)>& on_done) {
    struct Running {
        std::size_t index;
        Clock::time_point started;
    };
    std::map<pid_t, Running> running;
    std::size_t next = 0;
    while (next < commands.size() || !running.empty()) {
        while (next < commands.size() && static_cast<int>(running.size()) < std::max(1, jobs)) {
            const auto started = Clock::now();
            const pid_t pid = start(commands[next]);
            if (pid < 0) {
                on_done(next, ProcessResult{});
            } else {
                running[pid] = {next, started};
            }
            ++next;
        }
        if (running.empty()) {
            continue;
        }
        int status = 0;
        const pid_t pid = waitpid(-1, &status, 0);
        if (pid < 0) {
            if (errno == EINTR) {
                continue;
            }
            break; // no children left to wait for
        }
        const auto found = running.find(pid);
        if (found == running.end()) {
            continue; // a child this pool did not start
        }
        const Running done = found->second;
        running.erase(found);
        on_done(done.index, result_of(status, done.started));
    }
}

ProcessResult run_process(const ProcessSpec& command) {
    ProcessResult result;
    run_processes({command}, 1, [&](std::size_t, const ProcessResult& r) { result = r; });
    return result;
}

} // namespace grainload::app
