#include "app/resources/shell_cost.hpp"

#include "fem/shell_model.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace grainload::app {

namespace {

/// Steps of a segment beyond which its solved steps are not sought one by one: all count as
/// solved (an upper bound; a shell's own loads change over a few steps, its ramp).
constexpr double kStepsLookedAt = 1e5;

/// The histories that scale something: a step in which only others change finds the shell in
/// balance (no back-substitution, no factorisation).
std::vector<int> acting_histories(const fem::ShellAnalysis& analysis) {
    std::vector<int> acting;
    for (int h = 0; h < analysis.history_count(); ++h) {
        if (analysis.history_acts(h)) {
            acting.push_back(h);
        }
    }
    return acting;
}

/// ShellAnalysis::loads_change over the acting histories, with its tolerance.
bool loads_change(const fem::ShellAnalysis& analysis, const std::vector<int>& acting, double from,
                  double to) {
    return std::any_of(acting.begin(), acting.end(), [&](int h) {
        const double a = analysis.history_value(h, from);
        const double b = analysis.history_value(h, to);
        return std::abs(a - b) > 1e-12 * std::max({1.0, std::abs(a), std::abs(b)});
    });
}

/// How many of the segment's steps change the shell's loads.
double steps_changing_loads(const fem::ShellAnalysis& analysis, const std::vector<int>& acting,
                            const StepSegment& segment) {
    if (!loads_change(analysis, acting, segment.start, segment.start + segment.length)) {
        return 0.0; // a ramp's or time function's value the same at both ends: held
    }
    if (segment.count > kStepsLookedAt) {
        return segment.count;
    }
    const double dt = segment.length / segment.count;
    double changing = 0.0;
    for (double k = 0.0; k < segment.count; k += 1.0) {
        const double t = segment.start + k * dt;
        changing += loads_change(analysis, acting, t, t + dt) ? 1.0 : 0.0;
    }
    return changing;
}

/// Factorisations of a linear shell's tangent over a segment whose steps solve: a static one
/// keeps its first (`factorised_step` 0 once made); a dynamic one's effective tangent holds the
/// step (fem/newmark_integrator.hpp, tangent_key, compared exactly), so each change of the step
/// length makes a new one. The driver's steps are followed in its own arithmetic
/// (app/run_driver.cpp): dt = min(step, next output - t), t += dt, t set to the output instant
/// once within 1e-12 of the end time of it; so a last step that lands a round-off short of the
/// full step counts as the change it is. `end` is the run's end time.
double factorisations_in(const StepSegment& segment, bool dynamic, double end,
                         double& factorised_step) {
    if (!dynamic) {
        const bool first = factorised_step < 0.0;
        factorised_step = 0.0;
        return first ? 1.0 : 0.0;
    }
    double made = 0.0;
    const auto take = [&](double dt) {
        made += dt != factorised_step ? 1.0 : 0.0;
        factorised_step = dt;
    };
    const double next = segment.start + segment.length;
    if (segment.count > kStepsLookedAt) {
        take(segment.step);
        take(segment.last_step());
        return made;
    }
    const double tolerance = 1e-12 * end;
    for (double t = segment.start; t < next - tolerance;) {
        const double dt = std::min(segment.step, next - t);
        take(dt);
        t += dt;
    }
    return made;
}

/// Seconds of one factorisation of `dofs` free DOFs: the calibrated one scaled as DOFs^1.5.
double factorisation_seconds(double dofs, const Calibration& c) {
    return c.shell_factorisation_seconds *
           std::pow(dofs / std::max(c.shell_factorisation_dofs, 1.0), 1.5);
}

} // namespace

ShellCost estimate_shell_cost(const fem::ShellModel& fem, const std::vector<StepSegment>& steps,
                              bool coupled, bool loaded, const Calibration& c, double passes) {
    const fem::ShellAnalysis& analysis = fem.analysis();
    const auto dofs = static_cast<double>(analysis.free_dof_count());
    const auto elements = static_cast<double>(analysis.mesh().element_count());
    const bool linear = analysis.constant_tangent();
    const double end = steps.empty() ? 0.0 : steps.back().start + steps.back().length;
    const std::vector<int> acting = acting_histories(analysis);
    // A static step is advance_load's increments_per_step increments; a dynamic step is one.
    const double increments = fem.dynamic() ? 1.0 : static_cast<double>(fem.increments_per_step());
    ShellCost cost;
    double settled = 0.0; // coupled steps whose loads did not change
    double factorised_step = -1.0;
    for (const StepSegment& segment : steps) {
        if (!(segment.count > 0.0)) {
            continue;
        }
        const double solved = fem.dynamic() || (coupled && loaded)
                                  ? segment.count
                                  : steps_changing_loads(analysis, acting, segment);
        cost.steps += segment.count;
        cost.solved_steps += solved * passes;
        settled += coupled ? segment.count - solved : 0.0;
        if (linear && solved > 0.0) {
            cost.factorisations += factorisations_in(segment, fem.dynamic(), end, factorised_step);
        }
    }
    if (linear) {
        cost.back_substitutions = cost.solved_steps * increments;
        cost.seconds = cost.factorisations * factorisation_seconds(dofs, c) +
                       (cost.solved_steps > 0.0 ? elements * c.shell_seconds_per_element_assembly
                                                : 0.0) + // the stored stiffness, built once
                       increments * dofs *
                           (cost.solved_steps * c.shell_seconds_per_dof_solved_step +
                            settled * c.shell_seconds_per_dof_settled_step);
        return cost;
    }
    // Each correction assembles, factorises and back-substitutes; the increment's first
    // residual and every settled step assemble once more.
    const double corrections = cost.solved_steps * increments * kNonlinearCorrections;
    cost.factorisations = corrections;
    cost.back_substitutions = corrections;
    const double assemblies = corrections + (cost.solved_steps + settled) * increments;
    cost.seconds = corrections * (factorisation_seconds(dofs, c) +
                                  dofs * c.shell_seconds_per_dof_back_substitution) +
                   assemblies * elements * c.shell_seconds_per_element_assembly;
    return cost;
}

} // namespace grainload::app
