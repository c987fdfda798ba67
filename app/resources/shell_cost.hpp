#pragma once
// What a shell's steps will cost in factorisations and back-substitutions, before the run.

#include "app/resources/calibration.hpp"
#include "app/resources/step_plan.hpp"

#include <vector>

namespace grainload::fem {
class ShellModel;
}

namespace grainload::app {

/// What a shell's steps will cost, counted as the run counts them (fem/shell_model.hpp:
/// summary.json's fem_factorisations and fem_back_substitutions).
struct ShellCost {
    double steps = 0.0;        ///< steps (coupling windows) the shell advances
    double solved_steps = 0.0; ///< of which its loads change: a Newton solve
    double factorisations = 0.0;
    double back_substitutions = 0.0;
    double seconds = 0.0; ///< one thread's CPU seconds at the calibrated costs
};

/// Newton corrections per load increment of a shell whose tangent changes with its state
/// (large rotations, plasticity, follower loads): assumed, not counted before the run.
inline constexpr double kNonlinearCorrections = 3.0;

/// The cost of `fem`'s steps over `steps`:
///  - a linear shell (constant tangent: ShellAnalysis::constant_tangent) factorises its
///    tangent once, at its first solve, and keeps it (fem/newton_solver.hpp); a dynamic one
///    again whenever the step length changes (the effective tangent holds it). Each increment
///    whose loads changed is one back-substitution between two residuals K u from the stored
///    stiffness (the run may take a second where the drilling spring, in the tangent but not
///    in K u, leaves more than the force tolerance: a folded shell's first load); one whose
///    loads did not is one residual, and a shell alone (not `coupled`) skips such a step;
///  - another shell makes kNonlinearCorrections factorisations, back-substitutions and
///    element loops per increment.
/// A coupled shell with `loaded` parts (not all rigid) takes a new load every window; a rigid
/// one, or a shell alone, only while its loads change (the ramp to load_time, its time
/// functions); a dynamic shell solves every step. An iterated window solves the step once per
/// pass (`passes`, from the window's start each time; a linear shell keeps its factorisation).
ShellCost estimate_shell_cost(const fem::ShellModel& fem, const std::vector<StepSegment>& steps,
                              bool coupled, bool loaded, const Calibration& calibration,
                              double passes = 1.0);

} // namespace grainload::app
