#pragma once
// Piecewise-linear time functions that scale the shell's loads and prescribed values.

#include <utility>
#include <vector>

namespace grainload::fem {

/// Scale factor f(t) of a load or prescribed value: piecewise linear through (t_i, f_i) and
/// held at the end values outside them. A ramp to 1 at t_r is the points (0, 0), (t_r, 1).
class TimeFunction {
  public:
    explicit TimeFunction(std::vector<std::pair<double, double>> points);
    static TimeFunction ramp(double ramp_time) {
        return TimeFunction({{0.0, 0.0}, {ramp_time, 1.0}});
    }

    double operator()(double t) const;

  private:
    std::vector<std::pair<double, double>> points_;
};

} // namespace grainload::fem
