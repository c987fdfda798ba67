#include "app/resources/openmp_wait.hpp"

#include "app/resources/thread_count.hpp"

#include <cstdlib>
#include <string>
#include <unistd.h>

namespace grainload::app {

bool asks_auto_threads(char** argv) {
    for (int i = 1; argv[i] != nullptr; ++i) {
        if (std::string_view(argv[i]) == "--threads" && argv[i + 1] != nullptr &&
            std::string_view(argv[i + 1]) == "auto") {
            return true;
        }
    }
    return false;
}

std::string_view spin_count_for(int threads) {
    return threads >= 2 ? kQuietSpinCount : kSharedSpinCount;
}

namespace {

/// What default_openmp_wait took out of the environment in the program run again.
std::optional<int> taken_auto_threads;

} // namespace

std::optional<int> handed_auto_threads() {
    const char* text = std::getenv(kAutoThreadsVariable);
    if (text == nullptr) {
        return std::nullopt;
    }
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || value < 1 || value > 4096) {
        return std::nullopt;
    }
    return static_cast<int>(value);
}

int auto_threads() {
    if (taken_auto_threads) {
        return *taken_auto_threads;
    }
    return handed_auto_threads().value_or(auto_thread_count());
}

void default_openmp_wait(char** argv) {
#if defined(__linux__)
    // The program run again takes the count it was handed out of the environment, so that
    // no process it starts reads it as its own.
    taken_auto_threads = handed_auto_threads();
    unsetenv(kAutoThreadsVariable);
    if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) {
        return;
    }
    std::string_view spins = kSharedSpinCount;
    if (asks_auto_threads(argv)) {
        const int threads = auto_thread_count();
        if (setenv(kAutoThreadsVariable, std::to_string(threads).c_str(), 1) != 0) {
            return;
        }
        spins = spin_count_for(threads);
    }
    if (setenv("GOMP_SPINCOUNT", std::string(spins).c_str(), 1) == 0) {
        execv("/proc/self/exe", argv);
    }
#else
    (void)argv;
#endif
}

} // namespace grainload::app
