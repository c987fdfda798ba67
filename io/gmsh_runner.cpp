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

namespace {

/// The stamp's text: one `NAME VALUE` line per number, in the order given.
std::string numbers_stamp(const GmshNumbers& numbers) {
    std::ostringstream text;
    text.precision(17);
    for (const auto& [name, value] : numbers) {
        text << name << ' ' << value << '\n';
    }
    return text.str();
}

std::string stamp_path(const std::string& msh) {
    return msh + ".setnumber";
}

} // namespace

bool gmsh_mesh_outdated(const std::string& geo, const std::string& msh,
                        const GmshNumbers& numbers) {
    std::error_code error;
    const auto mesh_time = fs::last_write_time(msh, error);
    if (error || mesh_time < fs::last_write_time(geo)) {
        return true;
    }
    std::ifstream stamp(stamp_path(msh));
    const std::string made_with((std::istreambuf_iterator<char>(stamp)),
                                std::istreambuf_iterator<char>());
    return made_with != numbers_stamp(numbers);
}

bool ensure_gmsh_mesh(const std::string& geo, const std::string& msh, const GmshNumbers& numbers) {
    if (!gmsh_mesh_outdated(geo, msh, numbers)) {
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
    // The old stamp goes before the new mesh comes: a crash before the new stamp is written
    // leaves none, which reads as a mismatch (numbers given), never as up to date.
    std::error_code ignored_stamp;
    fs::remove(stamp_path(msh), ignored_stamp);
    commit_file(temporary, msh);
    if (!numbers.empty()) {
        write_file_atomically(stamp_path(msh),
                              [&](std::ostream& out) { out << numbers_stamp(numbers); });
    }
    return true;
}

} // namespace grainload::io
