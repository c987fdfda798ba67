#include "app/resources/blas_threads.hpp"

#include <dlfcn.h>

namespace grainload::app {

namespace {

/// OpenBLAS's own entry points (its cblas.h), looked up among the loaded libraries so that the
/// program neither links OpenBLAS by name nor fails on another BLAS.
template <typename Function> Function* openblas_function(const char* name) {
    return reinterpret_cast<Function*>(dlsym(RTLD_DEFAULT, name));
}

} // namespace

void follow_blas_threads(int threads) {
    if (auto* set = openblas_function<void(int)>("openblas_set_num_threads")) {
        set(threads);
    }
}

std::optional<int> blas_threads() {
    if (auto* get = openblas_function<int()>("openblas_get_num_threads")) {
        return get();
    }
    return std::nullopt;
}

} // namespace grainload::app
