#include "support/machine_load.hpp"

#include "app/resources/thread_count.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <thread>

namespace grainload::bench {

namespace {

std::vector<app::CpuTicks> cpu_ticks() {
    std::ifstream stat("/proc/stat");
    return app::parse_cpu_ticks(stat);
}

double wall_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

} // namespace

double process_cpu_seconds() {
    timespec time{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &time);
    return static_cast<double>(time.tv_sec) + 1e-9 * static_cast<double>(time.tv_nsec);
}

void LoadMeter::start() {
    ticks_ = cpu_ticks();
    own_seconds_ = process_cpu_seconds() + app::children_cpu_seconds();
    wall_seconds_ = wall_seconds();
}

double LoadMeter::others_cores() const {
    const double wall = wall_seconds() - wall_seconds_;
    const std::vector<app::CpuTicks> now = cpu_ticks();
    if (!(wall > 0.0) || now.size() != ticks_.size()) {
        return 0.0;
    }
    // Each CPU's busy share of its ticks since start(), summed: the busy cores.
    double busy = 0.0;
    for (std::size_t c = 0; c < now.size(); ++c) {
        const auto total = static_cast<double>(now[c].total - ticks_[c].total);
        busy += total > 0.0 ? static_cast<double>(now[c].busy - ticks_[c].busy) / total : 0.0;
    }
    const double own = (process_cpu_seconds() + app::children_cpu_seconds() - own_seconds_) / wall;
    return std::max(0.0, busy - own);
}

double wait_for_quiet(double quiet, double patience) {
    const double until = wall_seconds() + patience;
    for (;;) {
        LoadMeter meter;
        std::this_thread::sleep_for(std::chrono::seconds(1));
        const double load = meter.others_cores();
        if (load < quiet || wall_seconds() >= until) {
            return load;
        }
    }
}

} // namespace grainload::bench
