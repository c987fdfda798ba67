#pragma once
// Gates: the walls that leave the scene at a time, when it settles, or when a phase begins.

#include "particles/scene_part.hpp"
#include "particles/settle_watch.hpp"
#include "sph/wall.hpp"

#include <memory>
#include <vector>

namespace grainload::sph {

/// The walls with remove_at ([[sph.wall]]: a time, "settled" or "phase:NAME") as one scene
/// part: after the step whose end reaches a wall's removal time, or that settles the scene
/// (`settle`, null without [sph.settle]), the wall's particles leave. A phase sets the removal
/// time of the walls that wait for it when it begins; a removed wall keeps its place in the
/// wall list with no particles.
class GateSet final : public particles::ScenePart {
  public:
    GateSet(const std::vector<Wall>& walls, std::shared_ptr<const particles::SettlePart> settle)
        : walls_(&walls), settle_(std::move(settle)) {}

    /// Whether any of `walls` is a gate: it has a removal time, waits for the settle watch or
    /// for a phase.
    static bool any(const std::vector<Wall>& walls);

    std::string_view name() const override { return "sph.gate"; }
    Index collect_departures(const particles::ParticleView& particles, double time,
                             std::vector<char>& gone) override;

  private:
    const std::vector<Wall>* walls_;
    std::shared_ptr<const particles::SettlePart> settle_;
};

} // namespace grainload::sph
