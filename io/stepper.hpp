#pragma once
// One physics module as the driver's time loop sees it: stable step, advance, health, output.

#include "io/frame.hpp"

#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace grainload::io {

class OutputStreams;

/// One physics module as the time loop sees it (SPH, shell FEM, a coupled pair). The driver in
/// app/ owns the only time loop: it asks for the stable step, advances, checks health, and
/// collects frames, results and checkpoints at the same instants for every module.
class Stepper {
  public:
    virtual ~Stepper() = default;
    virtual std::string_view name() const = 0;
    /// Largest stable step (CFL for explicit SPH; +infinity for an implicit solver).
    virtual double stable_time_step() const = 0;
    /// Advance from t to t + dt.
    virtual void advance(double t, double dt) = 0;
    /// Number of computational points (particles, nodes) for particle-steps per second.
    virtual Index point_count() const = 0;
    /// Steps its own integrator has taken so far when they are not the driver's (a coupled
    /// model's SPH sub-steps of every window and pass): particle-steps per second count those.
    /// 0 by default: the module steps with the driver.
    virtual long long inner_steps() const { return 0; }
    /// std::nullopt when every field is finite and bounded; otherwise a diagnosis naming the
    /// particle/element and quantity ("particle 812 (body sand): velocity is NaN").
    virtual std::optional<std::string> diagnose() const = 0;
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
    /// Binary restart state; read_checkpoint must restore exactly what write_checkpoint saved.
    virtual void write_checkpoint(std::ostream& out) const = 0;
    virtual void read_checkpoint(std::istream& in) = 0;
};

} // namespace grainload::io
