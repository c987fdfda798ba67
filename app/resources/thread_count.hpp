#pragma once
// The thread count of --threads auto: the cores other processes leave free, from /proc/stat.

#include <istream>
#include <vector>

namespace grainload::app {

/// One CPU's time counters of /proc/stat (clock ticks since boot): busy is everything but
/// idle and iowait.
struct CpuTicks {
    unsigned long long busy = 0;
    unsigned long long total = 0;
};

/// How long `--threads auto` watches the machine: long enough to see a busy core (many
/// scheduler ticks of 4 ms), short against any run.
inline constexpr double kAutoThreadSample = 0.2;

/// The per-CPU lines ("cpu0 ...", "cpu1 ...") of a /proc/stat text, in order; the summary line
/// "cpu ..." is skipped. A text without them gives an empty vector.
std::vector<CpuTicks> parse_cpu_ticks(std::istream& stat);

/// The cores other processes leave free between two /proc/stat samples: the number of CPUs
/// less the busy ones (the sum over CPUs of busy / total ticks, less `own_cores`, the cores
/// this process itself kept busy meanwhile, rounded to the nearest core), at least 1. Samples
/// of different CPU counts or without ticks give the CPU count.
int free_cores(const std::vector<CpuTicks>& before, const std::vector<CpuTicks>& after,
               double own_cores = 0.0);

/// CPU seconds, user and system, this process has used (all its threads), and those of the
/// children it waited for (getrusage).
double own_cpu_seconds();
double children_cpu_seconds();

/// `--threads auto`: samples /proc/stat over `seconds` while the calling thread sleeps,
/// subtracts what this process's other threads used meanwhile (getrusage), and returns
/// free_cores; the CPU count of OpenMP where /proc/stat cannot be read. docs/performance.md
/// measures why a loaded machine wants fewer threads.
int auto_thread_count(double seconds = kAutoThreadSample);

} // namespace grainload::app
