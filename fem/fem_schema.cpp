#include "fem/fem_schema.hpp"

#include "fem/imported_shell_mesh_reader.hpp"
#include "fem/shell_case_reader.hpp"

#include <array>

namespace grainload::fem {

namespace {

constexpr std::string_view kGuide = "docs/user-guide/fem.md";
constexpr std::string_view kGmshHeading = "### Gmsh meshes (`generator = \"gmsh\"`)";

const std::array<io::KeyTable, 12> kTables{{
    {"fem", false, "the shell structure's analysis: static or dynamic, kinematics, Newton",
     kFemKeys, kGuide, "## `[fem]`"},
    {"fem.shell", true, "a shell part: its mesh source, thickness, material", kShellKeys, kGuide,
     "## `[[fem.shell]]`"},
    {"fem.shell", true, "a shell part's generated mesh: plate, cylinder, sphere_zone, cone, box",
     kShellGeneratorKeys, kGuide,
     "### Generated meshes (`plate`, `cylinder`, `sphere_zone`, `cone`, `box`)"},
    {"fem.shell", true, "a shell part meshed by Gmsh", kGmshKeys, kGuide, kGmshHeading},
    {"fem.shell.group", true, "a physical surface of a Gmsh mesh with its own thickness",
     kShellGroupKeys, kGuide, "#### `[[fem.shell.group]]`"},
    {"fem.shell.geo_numbers",
     false,
     "the numbers a Gmsh geometry script is given, by name",
     {},
     kGuide,
     kGmshHeading,
     true},
    {"fem.shell", true, "a shell part read from an LS-DYNA keyword deck", kKeywordShellKeys, kGuide,
     "### LS-DYNA keyword decks (`generator = \"lsdyna\"`)"},
    {"fem.shell.boundary", true, "supports, symmetry planes and prescribed motions of nodes",
     kBoundaryKeys, kGuide, "### `[[fem.shell.boundary]]`"},
    {"fem.shell.load", true, "a load on the part: area force, pressure, gravity, nodal", kLoadKeys,
     kGuide, "### `[[fem.shell.load]]`"},
    {"fem.shell.monitor", true, "a displacement or rotation reported in summary.json", kMonitorKeys,
     kGuide, "### `[[fem.shell.monitor]]`"},
    {"fem.shell.reaction", true, "the total support force on a node set, reported", kReactionKeys,
     kGuide, "### `[[fem.shell.reaction]]`"},
    {"fem.time_function", true, "a scale factor f(t) of loads and prescribed values",
     kTimeFunctionKeys, kGuide, "## `[[fem.time_function]]`"},
}};

} // namespace

std::span<const io::KeyTable> fem_key_tables() {
    return kTables;
}

} // namespace grainload::fem
