#pragma once
// How long OpenMP threads spin before they sleep, and the thread count of --threads auto.

#include <optional>
#include <string_view>

namespace grainload::app {

/// GOMP_SPINCOUNT of the product default: a thread that reaches the end of a parallel loop
/// first spins this many times and then sleeps. 1000 is about 0.1 ms on the 2-core AMD EPYC
/// machines this was first measured on (a PAUSE takes 92 ns there). libgomp's own default, 300 000
/// spins, made two threads 10-14x slower when other processes held a core: the thread with the work
/// waited for the core while its partner spun. Sleeping at once (OMP_WAIT_POLICY=passive)
/// costs a futex wake-up at each of the dozen parallel loops of a step on a quiet machine
/// (docs/performance.md).
inline constexpr std::string_view kSharedSpinCount = "1000";
/// GOMP_SPINCOUNT when `--threads auto` found at least two cores free as the program started:
/// on a quiet 2-core Intel Xeon the 2D collapse's steps took 1.33-1.36 s at 1000 spins, 1.00-1.07 s
/// at 30 000, where the wake-ups after sleeping cost what the spinning saves
/// (docs/performance.md, "Waiting threads").
inline constexpr std::string_view kQuietSpinCount = "30000";

/// The variable through which the program run again hands itself the thread count that
/// `--threads auto` measured before the exec, so that it is measured once.
inline constexpr const char* kAutoThreadsVariable = "GRAINLOAD_AUTO_THREADS";

/// The product default of OpenMP waiting, put into the environment before libgomp reads it:
/// kQuietSpinCount where the command line asks for `--threads auto` and auto_thread_count()
/// finds two or more cores free (the count is handed on in kAutoThreadsVariable), else
/// kSharedSpinCount. An explicit OMP_WAIT_POLICY or GOMP_SPINCOUNT wins.
///
/// libgomp reads both when it loads, before main, so this puts the default into the
/// environment and runs the program again, once (/proc/self/exe, Linux); call it first thing
/// in main. If the exec fails the program runs on with libgomp's default.
void default_openmp_wait(char** argv);

/// Whether argv holds `--threads auto`.
bool asks_auto_threads(char** argv);

/// The spin count of default_openmp_wait for `threads` threads found free.
std::string_view spin_count_for(int threads);

/// The thread count of `--threads auto`: the one measured before the program ran itself again
/// (kAutoThreadsVariable, a positive integer, which default_openmp_wait takes out of the
/// environment), else auto_thread_count() now.
int auto_threads();

/// kAutoThreadsVariable's count, when it holds a positive integer.
std::optional<int> handed_auto_threads();

} // namespace grainload::app
