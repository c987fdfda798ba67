#pragma once
// How busy the machine is beside a calibration, and waiting for it to be quiet.

#include "app/resources/thread_count.hpp"

#include <vector>

namespace grainload::bench {

/// How busy the machine is apart from this process: the busy share of each CPU's ticks in
/// /proc/stat (app/resources/thread_count.hpp), summed, less this process's own CPU time (all its
/// threads, and the children it waited for) over the wall time between start() and
/// others_cores(), in cores. A calibration reads it
/// to know whether its wall-time ratios (the speed-up of several threads) met a quiet machine.
class LoadMeter {
  public:
    LoadMeter() { start(); }
    void start();
    /// Other processes' mean use of the machine since start() [cores]; 0 when no time passed.
    double others_cores() const;

  private:
    std::vector<app::CpuTicks> ticks_; ///< at start()
    double own_seconds_ = 0.0;         ///< this process's and its children's CPU time at start()
    double wall_seconds_ = 0.0;
};

/// Samples the load for a second at a time until other processes use less than `quiet`
/// cores or `patience` seconds have passed; returns the last sample [cores].
double wait_for_quiet(double quiet, double patience);

/// This process's CPU time, all threads [s].
double process_cpu_seconds();

} // namespace grainload::bench
