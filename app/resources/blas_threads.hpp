#pragma once
// The BLAS threads of the shells' sparse factorisation, set to the run's thread count.

#include <optional>

namespace grainload::app {

/// Gives the BLAS under CHOLMOD the run's thread count, where that BLAS is OpenBLAS (Debian's
/// default `libblas.so.3` alternative). OpenBLAS otherwise takes OPENBLAS_NUM_THREADS,
/// OMP_NUM_THREADS or every core when it loads, whatever `--threads` says; its blocked
/// updates sum in an order that depends on its thread count, so a shell's support
/// reactions moved by 1.6e-6 N between one and two BLAS threads under the same `--threads 1`
/// (silo_janssen_small). With this, a run repeats itself bit for bit at a given `--threads`.
/// OpenBLAS is found at run time (dlsym): another BLAS alternative is left as it is.
void follow_blas_threads(int threads);

/// The BLAS's thread count, where the BLAS is OpenBLAS.
std::optional<int> blas_threads();

} // namespace grainload::app
