#pragma once
// The run's phases ([[phase]]), each ending at a stated time or on a condition.

#include "io/frame.hpp"
#include "particles/settle_watch.hpp"

#include <limits>
#include <string>
#include <vector>

namespace grainload::particles {

/// Whether a step ending at `time` reaches the stated time `due` (a phase's end, a wall's
/// remove_at): a step cut to an output instant can end an ulp short of it, and a time at an
/// output instant means that instant, so within 1e-12 of it counts (the tolerance of the
/// driver's own end time).
inline bool reaches(double time, double due) {
    return time >= due * (1.0 - 1e-12);
}

/// The run's phases as the case states them ([[phase]]): in order, each starting where the one
/// before ended, each ending at a stated time or on a condition (the scene settled, the sinks
/// took a mass). A phase's start is known as soon as every phase before it has ended or ends
/// at a stated time, so a time key that names it (`phase:NAME`) resolves before the run when
/// the phases before end on times, and when the condition is met otherwise. Checkpointed.
class PhaseSequence {
  public:
    enum class End { time, settled, discharged, run };
    struct Phase {
        std::string name;
        End end = End::run;
        double end_time = std::numeric_limits<double>::infinity(); ///< End::time, as stated
        double discharged_mass = 0.0;                              ///< End::discharged
        const char* mass_unit = "kg"; ///< of discharged_mass: "kg/m" in plane strain
        SettleWatch watch;            ///< End::settled
        // State (checkpointed):
        double start = std::numeric_limits<double>::infinity(); ///< +inf while unknown
        double finish = std::numeric_limits<double>::infinity();
        double discharged_at_start = 0.0;
    };

    PhaseSequence() = default;
    /// The phases in the case's order, their ends as stated (particles_case_reader.hpp reads
    /// them from the [[phase]] tables); the first starts at t = 0.
    explicit PhaseSequence(std::vector<Phase> phases);

    bool empty() const { return phases_.empty(); }
    const std::vector<Phase>& phases() const { return phases_; }
    bool ends_on(End end) const;
    /// The start of phase k; +infinity while it is not known.
    double start(int k) const { return phases_[static_cast<std::size_t>(k)].start; }

    /// After every step: the material's kinetic energy at its end, for the settle watches (each
    /// measures its peak from t = 0, as a standalone settle watch does).
    void record_kinetic(double time, double kinetic);
    /// After a step ending at `time`, with `discharged` the mass the sinks have taken so far:
    /// ends the current phase (and the next ones, whose end has come too) and returns one log
    /// line per phase ended.
    std::vector<std::string> update(double time, double discharged);

    /// summary.json's `phases`: every phase, the start null until it is reached.
    void append_records(std::vector<io::PhaseRecord>& records) const;
    std::vector<double> state() const;
    void set_state(const std::vector<double>& state);

  private:
    /// Fill in the starts that the phases ending at stated times fix, and start the watches.
    void propagate();
    std::string end_reason(const Phase& phase, double discharged) const;

    std::vector<Phase> phases_;
    std::size_t current_ = 0;
};

} // namespace grainload::particles
