#pragma once
// The SPH scene's monitors as scene parts: wall-load maps, the heap, the escape watch.

#include "particles/scene_part.hpp"
#include "particles/wall_map.hpp"
#include "sph/escape_watch.hpp"
#include "sph/heap_monitor.hpp"
#include "sph/wall.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace grainload::sph {

/// [[sph.wall_map]]: the maps sum the walls' loads after every step, each wall particle's force
/// standing for a patch of its spacing, and write their interval and window tables at the
/// output instants (particles/wall_map.hpp). `set` and `walls` are the solver's, observed
/// from then on.
std::unique_ptr<particles::ScenePart>
wall_map_part(particles::WallMapSet maps, const ParticleSet& set, const std::vector<Wall>& walls);

/// [sph.heap]: the measured body's kinetic energy at the end of every step, its heap's figures
/// in summary.json (sph/heap_monitor.hpp).
std::unique_ptr<particles::ScenePart> heap_part(HeapMonitor heap, const ParticleSet& particles);

/// The watchdog for particles leaving the scene (sph/escape_watch.hpp), naming a particle's
/// body by `body_name`.
std::unique_ptr<particles::ScenePart>
escape_part(EscapeWatch watch, const ParticleSet& particles,
            std::function<std::string(int body_id)> body_name);

} // namespace grainload::sph
