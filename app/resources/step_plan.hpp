#pragma once
// The time loop's steps to the end time, landing on every output instant, for the estimate.

#include <vector>

namespace grainload::app {

/// The time loop's steps in one output interval: `count` steps from `start` to start + length,
/// each the stable step `step` but the last, which lands on the output instant (the driver's
/// dt = min(stable step, next output - t)).
struct StepSegment {
    double start = 0.0;
    double length = 0.0;
    double count = 0.0;
    double step = 0.0;
    double last_step() const { return length - (count - 1.0) * step; }
};

/// A stable step that changes once: `rest`, and `flow` from `from` to `to` (the CFL step while
/// a discharge flows, app/cost_estimate.hpp); `rest` throughout when flow is 0.
struct StepProfile {
    double rest = 0.0;
    double flow = 0.0;
    double from = 0.0;
    double to = 0.0;
    double at(double t) const { return flow > 0.0 && t >= from && t < to ? flow : rest; }
    /// The steps [a, b] holds: the integral of 1 / step over it.
    double steps_over(double a, double b) const;
    bool changes_within(double a, double b) const { return flow > 0.0 && a < to && b > from; }
};

/// The time loop's steps from t = 0 to `end` at the stable step `driver`, landing on every
/// output instant (k `interval`) as the driver's loop does; with `sub_cycled` (a coupling
/// window) the SPH steps `ceil(window / step)` within each at the step `sph`, else one each.
/// Counted in doubles: a step of 1e-300 s gives more steps than a long long holds (a cast of
/// such a double is undefined behaviour), so `steps` stops at kMostSteps.
struct StepPlan {
    long long steps = 0;
    double sph_steps = 0.0;
    std::vector<StepSegment> segments;
};
inline constexpr double kMostSteps = 1e18;
StepPlan plan_steps(double end, double interval, const StepProfile& driver, const StepProfile& sph,
                    bool sub_cycled);

} // namespace grainload::app
