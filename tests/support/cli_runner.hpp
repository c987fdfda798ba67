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

/// The BLAS kernels the tests' runs use. OpenBLAS picks its kernels by the CPU (AVX-512 ones
/// on a machine that has it), and their sums differ in the last bits; a DEM packing on a
/// coupled shell amplifies those bits as any packing does, so its gold figures hold on one
/// kernel set only. Where the CPU has AVX2 the runs take OpenBLAS's AVX2 kernels
/// ("Haswell", the set it picks itself on AMD Zen), the set the gold files were written with
/// (scripts/update_gold.py); elsewhere, its own.
inline bool pin_blas_kernels() {
    return __builtin_cpu_supports("avx2");
}
inline constexpr const char* kPinnedBlasKernels = "Haswell";

/// Run `grainload <arguments>` (arguments already shell-quoted by the caller).
inline CliResult run_cli(const std::string& arguments, const std::string& log_file) {
    const std::string pinned =
        pin_blas_kernels() ? std::string("OPENBLAS_CORETYPE=") + kPinnedBlasKernels + " " : "";
    const std::string command =
        pinned + std::string(GRAINLOAD_EXECUTABLE) + " " + arguments + " > " + log_file + " 2>&1";
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
