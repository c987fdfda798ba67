#include "app/resources/step_plan.hpp"

#include <algorithm>
#include <cmath>

namespace grainload::app {

namespace {

/// Windows of one interval whose sub-steps are counted one by one when the SPH step changes
/// within it; beyond, its steps at the mean (the integral), rounded up.
constexpr double kWindowsLookedAt = 1e6;

/// SPH steps in `count` windows of `window` from `start`: ceil(window / step) each, the step
/// at each window's start (CoupledModel::subcycle).
double sub_steps(const StepProfile& sph, double start, double window, double count) {
    if (!sph.changes_within(start, start + window * count)) {
        return count * std::ceil(window / sph.rest * (1.0 - 1e-12));
    }
    if (count > kWindowsLookedAt) {
        return std::ceil(sph.steps_over(start, start + window * count));
    }
    double steps = 0.0;
    for (double k = 0.0; k < count; k += 1.0) {
        steps += std::ceil(window / sph.at(start + k * window) * (1.0 - 1e-12));
    }
    return steps;
}

} // namespace

double StepProfile::steps_over(double a, double b) const {
    double n = (b - a) / rest;
    if (flow > 0.0) {
        const double overlap = std::max(0.0, std::min(b, to) - std::max(a, from));
        n += overlap * (1.0 / flow - 1.0 / rest);
    }
    return n;
}

StepPlan plan_steps(double end, double interval, const StepProfile& driver, const StepProfile& sph,
                    bool sub_cycled) {
    StepPlan plan;
    const double tolerance = 1e-12 * end;
    // io/scene_settings.cpp holds end / interval to io::kMostOutputIntervals.
    const auto intervals = static_cast<long long>(std::ceil(end / interval - 1e-9));
    double steps = 0.0;
    for (long long k = 0; k < intervals; ++k) {
        const double start = static_cast<double>(k) * interval;
        const double stop = std::min(static_cast<double>(k + 1) * interval, end);
        const double length = stop - start;
        if (length <= tolerance) {
            continue;
        }
        const double n = std::ceil(driver.steps_over(start, stop) * (1.0 - 1e-12));
        steps += n;
        plan.segments.push_back({start, length, n, std::min(driver.at(start), length)});
        plan.sph_steps += sub_cycled ? sub_steps(sph, start, length / n, n) : n;
    }
    plan.steps = static_cast<long long>(std::min(steps, kMostSteps));
    return plan;
}

} // namespace grainload::app
