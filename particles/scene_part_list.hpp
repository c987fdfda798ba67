#pragma once
// The scene parts of one particle method, called in order at each point of a step.

#include "particles/scene_part.hpp"

#include <memory>
#include <vector>

namespace grainload::particles {

/// The parts of a scene in the order the case built them. Each point of a step calls every
/// part in that order, so their rows, figures and diagnoses keep it. The particle method
/// calls, per step: after_step, then (particles leave and enter) after_removal per removal,
/// end_step; at each output instant at_output; for summary.json append_results; every step
/// diagnose; and the checkpoint pair.
class ScenePartList {
  public:
    void add(std::unique_ptr<ScenePart> part) { parts_.push_back(std::move(part)); }
    bool empty() const { return parts_.empty(); }
    std::size_t size() const { return parts_.size(); }

    void after_step(double t, double dt);
    void end_step(double time);
    void after_removal(std::span<const Index> new_index);
    void at_output(double time, io::OutputStreams& output);
    void append_results(std::vector<io::ResultFigure>& results) const;
    /// The first part's diagnosis, in order.
    std::optional<std::string> diagnose() const;
    /// The part count, then per part its name and its state: a restart whose case builds other
    /// parts than the run that wrote the checkpoint is refused, naming the part.
    void write_checkpoint(std::ostream& out) const;
    void read_checkpoint(std::istream& in);

  private:
    std::vector<std::unique_ptr<ScenePart>> parts_;
};

} // namespace grainload::particles
