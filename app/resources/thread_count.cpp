#include "app/resources/thread_count.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <omp.h>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <thread>

namespace grainload::app {

std::vector<CpuTicks> parse_cpu_ticks(std::istream& stat) {
    std::vector<CpuTicks> cpus;
    std::string line;
    while (std::getline(stat, line)) {
        // "cpuN user nice system idle iowait irq softirq steal ..." (proc(5)); "cpu " is the
        // machine's sum.
        if (line.size() < 4 || line.compare(0, 3, "cpu") != 0 || line[3] == ' ') {
            continue;
        }
        std::istringstream fields(line);
        std::string name;
        fields >> name;
        CpuTicks ticks;
        unsigned long long value = 0;
        for (int field = 0; field < 8 && fields >> value; ++field) {
            ticks.total += value;
            const bool waiting = field == 3 || field == 4; // idle, iowait
            ticks.busy += waiting ? 0 : value;
        }
        cpus.push_back(ticks);
    }
    return cpus;
}

int free_cores(const std::vector<CpuTicks>& before, const std::vector<CpuTicks>& after,
               double own_cores) {
    const int cpus = static_cast<int>(after.size());
    if (cpus == 0 || before.size() != after.size()) {
        return std::max(cpus, 1);
    }
    double busy = 0.0;
    for (std::size_t c = 0; c < after.size(); ++c) {
        const double total = static_cast<double>(after[c].total - before[c].total);
        if (total > 0.0) {
            busy += static_cast<double>(after[c].busy - before[c].busy) / total;
        }
    }
    busy = std::max(0.0, busy - own_cores);
    return std::max(1, cpus - static_cast<int>(std::lround(busy)));
}

namespace {

std::vector<CpuTicks> read_cpu_ticks() {
    std::ifstream stat("/proc/stat");
    return parse_cpu_ticks(stat);
}

/// User and system CPU seconds of getrusage(who).
double rusage_seconds(int who) {
    rusage usage{};
    getrusage(who, &usage);
    const auto seconds = [](const timeval& t) {
        return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
    };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

} // namespace

double own_cpu_seconds() {
    return rusage_seconds(RUSAGE_SELF);
}

double children_cpu_seconds() {
    return rusage_seconds(RUSAGE_CHILDREN);
}

int auto_thread_count(double seconds) {
    // This process's own threads are not other work: libopenblas (pthreads build, linked for
    // CHOLMOD) starts its pool when the program loads, and the pool spins for about 0.1 s of
    // CPU, more than half a core over the sample.
    const auto start = std::chrono::steady_clock::now();
    const double own_start = own_cpu_seconds();
    const std::vector<CpuTicks> before = read_cpu_ticks();
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    const std::vector<CpuTicks> after = read_cpu_ticks();
    const double own = own_cpu_seconds() - own_start;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (after.empty()) {
        return omp_get_num_procs();
    }
    return std::min(free_cores(before, after, own / std::max(elapsed, 1e-3)), omp_get_num_procs());
}

} // namespace grainload::app
