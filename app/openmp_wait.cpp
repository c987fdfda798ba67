#include "app/openmp_wait.hpp"

#include <cstdlib>
#include <unistd.h>

namespace grainload::app {

void default_openmp_wait(char** argv) {
#if defined(__linux__)
    if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) {
        return;
    }
    if (setenv("GOMP_SPINCOUNT", "1000", 1) == 0) {
        execv("/proc/self/exe", argv);
    }
#else
    (void)argv;
#endif
}

} // namespace grainload::app
