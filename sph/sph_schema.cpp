#include "sph/sph_schema.hpp"

#include "sph/phase_sequence.hpp"
#include "sph/settle_watch.hpp"
#include "sph/sink.hpp"
#include "sph/source.hpp"
#include "sph/symmetry.hpp"
#include "sph/wall_map.hpp"

#include <array>

namespace grainload::sph {

namespace {

constexpr std::string_view kGuide = "docs/user-guide/sph.md";

const std::array<io::KeyTable, 7> kTables{{
    {"sph.wall", true, "a wall that leaves the scene or moves on a schedule: an outlet, a gate",
     kWallOutletKeys, kGuide, "## Outlets and gates: `[[sph.wall]]` keys"},
    {"sph.source", true, "particles entering the scene through a region at a mass rate",
     kSourceKeys, kGuide, "## `[[sph.source]]`"},
    {"sph.sink", true, "particles leaving the scene beyond a plane or inside a box", kSinkKeys,
     kGuide, "## `[[sph.sink]]`"},
    {"sph.settle", false, "when the scene counts as settled (`settled` in time keys)", kSettleKeys,
     kGuide, "## Settling: `[sph.settle]`"},
    {"sph.symmetry", true, "a mirror plane: the scene is a half or a quarter of the whole",
     kSymmetryKeys, kGuide, "## Symmetry planes: `[[sph.symmetry]]`"},
    {"sph.wall_map", true, "the wall pressure and friction in bins over a wall's surface",
     kWallMapKeys, kGuide, "## `[[sph.wall_map]]`"},
    {"phase", true, "a named stage of the run (fill, settle, discharge) that starts on an event",
     kPhaseKeys, kGuide, "## Phases: `[[phase]]`"},
}};

} // namespace

std::span<const io::KeyTable> sph_key_tables() {
    return kTables;
}

} // namespace grainload::sph
