#pragma once
// Piecewise-linear time functions that scale the shell's loads and prescribed values.

#include "io/key_spec.hpp"

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace grainload::io {
class CaseTable;
}

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

/// The keys of each [[fem.time_function]] table.
inline constexpr std::array<io::KeySpec, 4> kTimeFunctionKeys{{
    {"name", "string", "", "referenced by `time_function` in loads and boundary conditions"},
    {"type", "`points` or `ramp`", "`\"points\"`", "piecewise linear through `points`, or a ramp"},
    {"points", "list of [time, number] pairs", "required for `points`",
     "f(t) piecewise linear, times increasing, held at the end values outside them"},
    {"ramp_time", "time", "required for `ramp`", "f = min(t / ramp_time, 1)"},
}};

/// The case's [[fem.time_function]] tables by name (see docs/user-guide/fem.md).
std::map<std::string, TimeFunction> read_time_functions(const io::CaseTable& fem);

} // namespace grainload::fem
