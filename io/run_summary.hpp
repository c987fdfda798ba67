#pragma once
// What summary.json holds at the end of a run, and its atomic write.

#include "io/frame.hpp"

#include <optional>
#include <string>
#include <vector>

namespace grainload::io {

/// What summary.json holds at the end of a run (or when it stops on an instability).
struct RunSummary {
    std::string case_name;
    std::string case_file;
    /// The command line's --set key=value, in order: with case_file, what was run (the
    /// trade tool's and the analysis scripts' variants differ only here).
    std::vector<std::string> overrides;
    int threads = 1;
    double wall_time = 0.0; ///< s
    /// CPU time of the process over the same span, all threads [s]: what a loaded machine does
    /// not stretch, for the estimate's ratios (absent where not measured).
    std::optional<double> cpu_time;
    double simulated_time = 0.0;
    Index steps = 0;
    Index points = 0; ///< particles + shell nodes
    /// Points of the material: the SPH body particles, without the wall particles (boundary,
    /// not material) and the shell nodes (which have their own rate below).
    /// particle_steps_per_second counts these.
    Index material_points = 0;
    Index shell_nodes = 0;
    std::string status = "completed"; ///< "completed" or "unstable"
    std::string diagnosis;
    std::vector<ResultFigure> results;
    std::vector<ModelChoice> model;  ///< what was modelled (Reporter::describe_model)
    std::vector<std::string> hints;  ///< what could have been left out (Reporter::append_hints)
    std::vector<PhaseRecord> phases; ///< the case's [[phase]] table as the run went through it
    /// What `grainload check` estimated before the run (app/cost_estimate.hpp); written with
    /// the ratios actual / estimated when set.
    std::optional<double> estimated_steps;
    std::optional<double> estimated_wall_time; ///< s
    /// The shell's factorisations and back-substitutions the estimate foresaw (with a shell)
    /// and the calibration it used (app/resources/calibration.hpp, describe_calibration).
    std::optional<double> estimated_factorisations;
    std::optional<double> estimated_back_substitutions;
    std::string estimate_calibration;

    /// Material points summed over the steps this process ran (empty: not counted); when
    /// counted, the rate is this over wall_time, which a discharge (points leaving) needs, and
    /// a restart that ran no step (restarted from its final checkpoint) has a rate of 0.
    std::optional<double> material_point_steps;
    /// material_point_steps / wall_time, or material_points * steps / wall_time.
    double point_steps_per_second() const;
    /// Shell nodes summed over the steps this process ran (a coupling window is one step of
    /// the shell), for shell_node_steps_per_second.
    double shell_node_steps = 0.0;
};

/// Write `summary` as JSON to `path` atomically. Each result becomes
/// {"value", "unit"[, "reference", "source", "relative_error"]}.
void write_run_summary(const RunSummary& summary, const std::string& path);

} // namespace grainload::io
