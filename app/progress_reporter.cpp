#include "app/progress_reporter.hpp"

#include <cstdio>
#include <iostream>

namespace grainload::app {

ProgressReporter::ProgressReporter(io::StreamedFile& log, double end_time)
    : log_(log), end_time_(end_time), start_(Clock::now()), last_print_(start_) {}

double ProgressReporter::elapsed_seconds() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
}

void ProgressReporter::message(const std::string& text) {
    std::cerr << text << '\n';
    log_.append(text + '\n');
}

void ProgressReporter::update(double t, long long step, double dt, double point_steps, bool force) {
    if (start_time_ < 0.0) {
        start_time_ = t; // a restarted run measures its rate from where it resumed
        start_point_steps_ = point_steps;
    }
    const auto now = Clock::now();
    if (!force && now - last_print_ < std::chrono::seconds(1)) {
        return;
    }
    last_print_ = now;
    const double elapsed = elapsed_seconds();
    const double done = (t - start_time_) / (end_time_ - start_time_);
    const double eta = done > 0.0 ? elapsed * (1.0 - done) / done : 0.0;
    const double rate = elapsed > 0.0 ? (point_steps - start_point_steps_) / elapsed : 0.0;
    char line[200];
    std::snprintf(line, sizeof line,
                  "t = %.5g / %.5g s  step %lld  dt = %.3e s  ETA %.0f s  %.3e particle-steps/s", t,
                  end_time_, step, dt, eta, rate);
    message(line);
}

} // namespace grainload::app
