#pragma once
// A scene's shell model as the case's [fem] table and its [[fem.shell]] tables state it.

#include "fem/shell_model.hpp"
#include "io/scene_settings.hpp"
#include "materials/material_library.hpp"

#include <memory>

namespace grainload::io {
class CaseTable;
}

namespace grainload::fem {

/// The analysis settings of [fem] (docs/user-guide/fem.md); `end_time` is load_time's default.
ShellModelSettings read_shell_model_settings(const io::CaseTable& fem, double end_time);

/// The shell model of the case's [fem] table: its settings, the mesh and parts of every
/// [[fem.shell]], their time functions, supports, loads, monitors and reactions.
std::unique_ptr<ShellModel> read_shell_model(const io::CaseTable& root,
                                             const io::SceneSettings& scene,
                                             const materials::MaterialLibrary& materials);

} // namespace grainload::fem
