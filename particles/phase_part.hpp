#pragma once
// The run's phases ([[phase]]) as a scene part any particle method holds.

#include "particles/phase_sequence.hpp"
#include "particles/scene_part.hpp"

#include <functional>
#include <string>
#include <vector>

namespace grainload::particles {

/// The phases of a run as one scene part: what they read of the method (its kinetic energy for
/// a phase that ends on settling, the sinks' discharged mass for one that ends on it) and what
/// they set in it (the walls and sources whose times name a phase) come through hooks, so SPH
/// and the DEM hold the same part. It records the kinetic energy after each step, logs each
/// phase's end, reports the settle figures and carries the sequence's checkpoint state. Its
/// ends are advanced by the method (advance), which orders the step's departures around them:
/// a phase that ends on a time or on settling does so before the step's removals, one that
/// ends on the mass the sinks took only after them.
class PhasePart : public ScenePart {
  public:
    struct Hooks {
        /// The material's kinetic energy after a step (read only when a phase ends on settling).
        std::function<double()> kinetic_energy;
        /// The mass the sinks have taken since t = 0 (read only when a phase ends on it).
        std::function<double()> discharged;
        /// The phases' starts are known or changed: hand them to what names them.
        std::function<void(const PhaseSequence&)> apply_starts;
    };

    /// `report_settle`: summary.json carries the first settle phase's figures (a case that also
    /// has a standalone settle watch reports that one's instead).
    PhasePart(PhaseSequence phases, Hooks hooks, bool report_settle);

    const PhaseSequence& sequence() const { return phases_; }
    /// After a step ending at `time`: ends the phases whose end came, logs them and hands the
    /// new starts over; true when a phase ended.
    bool advance(double time);
    /// Hand the starts known now over (once the walls and sources that name them are built).
    void apply_starts() const;

    std::string_view name() const override { return "phase"; }
    void after_step(double t, double dt) override;
    void append_results(std::vector<io::ResultFigure>& results) const override;
    void take_events(std::vector<std::string>& events) override;
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

  private:
    PhaseSequence phases_;
    Hooks hooks_;
    bool report_settle_ = true;
    std::vector<std::string> events_;
};

} // namespace grainload::particles
