#pragma once
// The scene-wide [case] keys (gravity, end time, output interval), read once for every module.

#include "io/key_spec.hpp"
#include "io/types.hpp"

#include <array>
#include <string>

namespace grainload::io {

class CaseDocument;

/// The scene-wide [case] keys, read once (read_scene_settings) and handed to every module, so
/// that SPH, shells and the coupling cannot disagree on gravity or the end time.
struct SceneSettings {
    std::string name;
    int dimension = 3;
    double end_time = 0.0;
    double output_interval = 0.0;
    Vec3 gravity = Vec3::Zero();

    /// Index of the vertical axis of the scene: z in 3D, y in plane strain (x-y plane).
    int up_axis() const { return dimension == 2 ? 1 : 2; }
};

/// Standard gravity as the cases have always used it (3 significant digits, m/s^2).
inline constexpr double kDefaultGravity = 9.81;

/// Output intervals a run may have up to end_time: a frame and a checkpoint are written at
/// each, so more than a million is a mistyped interval (1e-12 s for 1e-3 s), which `grainload
/// check` used to count one by one (minutes) and a run would write for days.
inline constexpr double kMostOutputIntervals = 1e6;

/// The [case] table's keys with their defaults (docs/user-guide.md, "[case]").
inline constexpr std::array<KeySpec, 5> kCaseKeys{{
    {"name", "string", "file name without `.toml`",
     "names the output: `<name>.pvd`, frames `<name>_NNNNNN.vtm`"},
    {"dimension", "2 or 3", "3", "2 is plane strain in the x–y plane (z = 0)", 3.0},
    {"end_time", "time", "", "simulated time at which the run stops"},
    {"output_interval", "time", "`end_time / 20`",
     "frames (and checkpoints) at every multiple of it, and at `end_time`"},
    {"gravity", "acceleration vector",
     "−9.81 m/s² along the up axis: `\"0 0 -9.81 m/s^2\"` "
     "(3D), `\"0 -9.81 m/s^2\"` (2D)",
     "body force per unit mass, for every module (SPH bodies, shell gravity loads)"},
}};

/// Reads [case] of the document; `file_stem` is the default name. Sets the document's spatial
/// dimension, which vector keys need, before reading gravity.
SceneSettings read_scene_settings(CaseDocument& document, const std::string& file_stem);

} // namespace grainload::io
