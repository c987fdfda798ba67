#include "io/io_schema.hpp"

#include "io/figure_reference.hpp"
#include "io/scene_settings.hpp"

#include <array>

namespace grainload::io {

namespace {

const std::array<KeyTable, 2> kTables{{
    {"case", false, "scene-wide settings every module reads", kCaseKeys, "docs/user-guide.md",
     "## `[case]`"},
    {"case.reference", true, "a figure of summary.json with the published value it is read against",
     kFigureReferenceKeys, "docs/user-guide.md", "## `[[case.reference]]`"},
}};

} // namespace

std::span<const KeyTable> io_key_tables() {
    return kTables;
}

} // namespace grainload::io
