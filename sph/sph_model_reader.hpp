#pragma once
// The SPH side of a scene as the case's [sph] tables (and [[phase]]) state it.

#include "io/scene_settings.hpp"
#include "materials/material_library.hpp"
#include "sph/sph_model.hpp"

#include <memory>

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// The whole [sph] table of `root`: bodies, walls, solver and the scene's parts.
std::unique_ptr<SphModel> read_sph_model(const io::CaseTable& root, const io::SceneSettings& scene,
                                         const materials::MaterialLibrary& materials);

/// The [sph] settings and the [[sph.body]] bodies only, for a caller that adds walls of its own
/// (SphModel::add_wall) before build_sph_scene.
std::unique_ptr<SphModel> read_sph_bodies(const io::CaseTable& root, const io::SceneSettings& scene,
                                          const materials::MaterialLibrary& materials);

/// Completes a model read_sph_bodies returned: the [[sph.wall]] walls, then the added ones;
/// friction, symmetry and periodic boundaries, the solver; probes, sinks, the settle watch,
/// gates, sources and phases; wall maps, the heap and the escape watch; and the start checks,
/// which refuse at, or warn naming, the keys involved.
void build_sph_scene(SphModel& model, const io::CaseTable& root);

} // namespace grainload::sph
