#pragma once
// The run's progress line: simulated time, step, dt, ETA and particle-steps per second.

#include "io/output_streams.hpp"

#include <chrono>
#include <string>

namespace grainload::app {

/// One progress line at most once a second, on stderr and in the run's log.txt:
/// simulated time / end time, step, dt, ETA and particle-steps per second.
class ProgressReporter {
  public:
    ProgressReporter(io::StreamedFile& log, double end_time);

    /// `point_steps`: the run's material point-steps so far (sub-steps of coupled windows
    /// counted), for the particle-steps per second it prints.
    void update(double t, long long step, double dt, double point_steps, bool force = false);
    /// A message for both stderr and the log.
    void message(const std::string& text);
    double elapsed_seconds() const;

  private:
    using Clock = std::chrono::steady_clock;
    io::StreamedFile& log_;
    double end_time_;
    Clock::time_point start_;
    Clock::time_point last_print_;
    double start_time_ = -1.0;
    double start_point_steps_ = 0.0;
};

} // namespace grainload::app
