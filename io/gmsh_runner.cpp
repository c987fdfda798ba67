#include "io/gmsh_runner.hpp"

#include "io/atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <spawn.h>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace grainload::io {

namespace {

namespace fs = std::filesystem;

/// Gmsh's lines that say what went wrong ("Error   : ..."), else the last lines of its log.
std::string gmsh_complaint(const std::string& log) {
    std::ifstream in(log);
    std::vector<std::string> lines, errors;
    std::string line;
    while (std::getline(in, line)) {
        if (line.find("Error") != std::string::npos) {
            errors.push_back(line);
        }
        lines.push_back(line);
    }
    const auto& shown = errors.empty() ? lines : errors;
    std::string text;
    const std::size_t first = shown.size() > 8 ? shown.size() - 8 : 0;
    for (std::size_t k = first; k < shown.size(); ++k) {
        text += "\n  " + shown[k];
    }
    return text;
}

/// Runs gmsh with `args`, its output into `log`; returns the exit status (-1: not started).
int run_gmsh(std::vector<std::string> args, const std::string& log, int* spawn_error) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    std::vector<char*> argv;
    for (std::string& arg : args) {
        argv.push_back(arg.data());
    }
    argv.push_back(nullptr);
    pid_t pid = 0;
    *spawn_error = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (*spawn_error != 0) {
        return -1;
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) {
            return -1;
        }
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

} // namespace

bool gmsh_mesh_outdated(const std::string& geo, const std::string& msh) {
    std::error_code error;
    const auto mesh_time = fs::last_write_time(msh, error);
    return error || mesh_time < fs::last_write_time(geo);
}

bool ensure_gmsh_mesh(const std::string& geo, const std::string& msh,
                      const std::vector<std::pair<std::string, double>>& numbers) {
    if (!gmsh_mesh_outdated(geo, msh)) {
        return false;
    }
    // Names of this process's own: two runs meshing the same file do not share them.
    const std::string tag = ".tmp" + std::to_string(getpid());
    const std::string temporary = msh + tag + ".msh";
    const std::string log = msh + tag + ".log";
    int spawn_error = 0;
    std::vector<std::string> args{"gmsh", geo, "-2", "-format", "msh41", "-o", temporary};
    for (const auto& [name, value] : numbers) {
        std::ostringstream text;
        text.precision(17);
        text << value;
        args.insert(args.end(), {"-setnumber", name, text.str()});
    }
    const int status = run_gmsh(std::move(args), log, &spawn_error);
    const std::string complaint = gmsh_complaint(log);
    std::error_code ignored;
    fs::remove(log, ignored);
    if (status < 0) {
        throw std::invalid_argument(
            "cannot run gmsh to mesh " + geo + ": " + std::strerror(spawn_error) +
            (spawn_error == ENOENT
                 ? " (install the Debian package gmsh; scripts/ensure_packages.sh "
                   "does)"
                 : ""));
    }
    const bool errors = complaint.find("Error") != std::string::npos;
    if (status != 0 || errors || !fs::is_regular_file(temporary)) {
        fs::remove(temporary, ignored);
        throw std::invalid_argument("gmsh failed to mesh " + geo + " (exit status " +
                                    std::to_string(status) + "):" + complaint);
    }
    commit_file(temporary, msh);
    return true;
}

} // namespace grainload::io
