#pragma once
// One physics module as the run's output sees it: frames, figures, model, hints, events, logs.

#include "io/frame.hpp"

#include <string>
#include <vector>

namespace grainload::io {

class OutputStreams;

/// What a physics module reports (SPH, shell FEM, a coupled pair), apart from how it steps
/// (io::Stepper): the driver collects frames, results and logs from every module at the same
/// output instants, the events after each step, and the model statement, hints and phases for
/// summary.json.
class Reporter {
  public:
    virtual ~Reporter() = default;
    /// Its blocks of the frame collected at an output instant (frame.time).
    virtual void append_blocks(Frame& frame) const = 0;
    /// The case's own figures at time t, for summary.json.
    virtual void append_results(double t, std::vector<ResultFigure>& results) const = 0;
    /// What the module models, item by item, for summary.json's "model". Nothing by default.
    virtual void describe_model(std::vector<ModelChoice>& choices) const { (void)choices; }
    /// After the run: what the scene could have left out, with the numbers that say so (a cap
    /// that was never reached, a shell that hardly moved), for the log and summary.json's
    /// "hints". Nothing by default.
    virtual void append_hints(std::vector<std::string>& hints) const { (void)hints; }
    /// Events of the steps since the last call (a phase that ended: "settled at 2.1 s"), one
    /// line each, which the driver writes to the run's log. None by default.
    virtual std::vector<std::string> take_events() { return {}; }
    /// The run's phases ([[phase]]) for summary.json's "phases". None by default.
    virtual void append_phases(std::vector<PhaseRecord>& records) const { (void)records; }
    /// Append the module's own logs since the last call to the run's streams (the shell FEM's
    /// per-step convergence CSV, the coupling's windows); called at every output instant,
    /// before the checkpoint records where the streams stand. Nothing by default.
    virtual void write_logs() const {}
    /// The run's output: its directory and the streamed files (io/output_streams.hpp) a module
    /// appends its tables to (wall_forces.csv, ...). Called once by the driver before the first
    /// step and outliving the module's run; a module without such tables ignores it.
    virtual void set_output(OutputStreams& output) { (void)output; }
};

} // namespace grainload::io
