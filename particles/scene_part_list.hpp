#pragma once
// The scene parts of one particle method, called in order at each point of a step.

#include "particles/scene_part.hpp"

#include <memory>
#include <vector>

namespace grainload::particles {

/// The parts of a scene in the order the case built them. Each point of a step calls every
/// part in that order, so their rows, figures and diagnoses keep it. The particle method
/// calls, per step: after_step; collect_departures, then after_removal when particles left;
/// collect_arrivals; end_step; take_events and diagnose; at each output instant at_output; for
/// summary.json append_results; and the checkpoint pair. A part may be shared with the model that
/// reads it (the sinks' discharged mass, the settle watch's time).
class ScenePartList {
  public:
    void add(std::shared_ptr<ScenePart> part) { parts_.push_back(std::move(part)); }
    bool empty() const { return parts_.empty(); }
    std::size_t size() const { return parts_.size(); }

    void after_step(double t, double dt);
    void end_step(double time);
    /// Every part's departures, in order (see ScenePart::collect_departures); the count.
    Index collect_departures(const ParticleView& particles, double time, std::vector<char>& gone);
    void after_removal(std::span<const Index> new_index);
    /// Every part's arrivals over [t, t + dt], in order.
    std::vector<Arrival> collect_arrivals(const ParticleView& particles, double t, double dt);
    void at_output(double time, io::OutputStreams& output);
    void append_results(std::vector<io::ResultFigure>& results) const;
    /// Every part's events, in order.
    std::vector<std::string> take_events();
    /// The first part's diagnosis, in order.
    std::optional<std::string> diagnose() const;
    /// The part count, then per part its name and its state: a restart whose case builds other
    /// parts than the run that wrote the checkpoint is refused, naming the part.
    void write_checkpoint(std::ostream& out) const;
    void read_checkpoint(std::istream& in);

  private:
    std::vector<std::shared_ptr<ScenePart>> parts_;
};

} // namespace grainload::particles
