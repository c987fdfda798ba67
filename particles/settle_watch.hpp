#pragma once
// The [sph.settle] watch: the step whose kinetic energy falls below a fraction of its largest.

#include "particles/scene_part.hpp"

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace grainload::particles {

/// A settle phase that ends itself: from `after` on, the first step whose material kinetic
/// energy falls below `fraction` of the largest it has had since t = 0 is the settle time,
/// after which walls with remove_at = "settled" leave. Checkpointed.
class SettleWatch {
  public:
    SettleWatch() = default;
    SettleWatch(double fraction, double after) : fraction_(fraction), after_(after) {}

    /// After a step ending at `time` with kinetic energy `kinetic`: true on the step that
    /// settles.
    bool record(double time, double kinetic);
    bool settled() const { return settle_time_ < std::numeric_limits<double>::infinity(); }
    double settle_time() const { return settle_time_; }
    double peak() const { return peak_; }
    double fraction() const { return fraction_; }
    /// Move the watch's start (a phase's start, known only once the phase before it ended).
    void set_after(double after) { after_ = after; }

    std::vector<double> state() const { return {peak_, settle_time_}; }
    void set_state(const std::vector<double>& state);

  private:
    double fraction_ = 0.0;
    double after_ = 0.0;
    double peak_ = 0.0;
    double settle_time_ = std::numeric_limits<double>::infinity();
};

/// [sph.settle] as a scene part: after every step it gives the watch the material's kinetic
/// energy (read through `kinetic_energy`), says when the scene settled (an event for the log),
/// reports settle_time and settle_peak_kinetic_energy, and checkpoints the watch.
class SettlePart final : public ScenePart {
  public:
    SettlePart(SettleWatch watch, std::function<double()> kinetic_energy)
        : watch_(watch), kinetic_energy_(std::move(kinetic_energy)) {}
    const SettleWatch& watch() const { return watch_; }

    std::string_view name() const override { return "settle"; }
    void after_step(double t, double dt) override;
    void take_events(std::vector<std::string>& events) override;
    void append_results(std::vector<io::ResultFigure>& results) const override;
    void write_checkpoint(std::ostream& out) const override;
    void read_checkpoint(std::istream& in) override;

  private:
    SettleWatch watch_;
    std::function<double()> kinetic_energy_;
    std::vector<std::string> events_;
};

/// The figures of a settle watch for summary.json: settle_time (null while not settled) and
/// settle_peak_kinetic_energy.
void append_settle_results(const SettleWatch& watch, std::vector<io::ResultFigure>& results);

} // namespace grainload::particles
