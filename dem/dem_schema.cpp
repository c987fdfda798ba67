#include "dem/dem_schema.hpp"

#include "dem/dem_case_reader.hpp"
#include "io/surface_mesh_reader.hpp"
#include "particles/particles_case_reader.hpp"
#include "particles/wall_map_reader.hpp"

#include <array>

namespace grainload::dem {

namespace {

constexpr std::string_view kGuide = "docs/user-guide/dem.md";

const std::array<io::KeyTable, 9> kTables{{
    {"dem", false, "the discrete element method: its step and neighbour search", kDemKeys, kGuide,
     "### `[dem]`"},
    {"dem.contact", false, "the contact law between grains and with walls", kDemContactKeys, kGuide,
     "### `[dem.contact]`"},
    {"dem.body", true, "a body of spherical grains: material, radii, placement", kDemBodyKeys,
     kGuide, "### `[[dem.body]]`"},
    {"dem.wall", true, "a rigid wall of flat faces: a plane, a rectangle or a box", kDemWallKeys,
     kGuide, "### `[[dem.wall]]`"},
    {"dem.wall", true, "a mesh wall's surface", io::kSurfaceMeshKeys, kGuide,
     "### Mesh walls: `[[dem.wall]]` type = \"mesh\""},
    {"dem.triaxial", false, "a triaxial cell: servo side walls at a confining stress, a platen",
     kDemTriaxialKeys, kGuide, "### `[dem.triaxial]`"},
    {"dem.sink", true, "a region grains leave the scene through", particles::kSinkKeys, kGuide,
     "### `[[dem.sink]]`"},
    {"dem.source", true, "a box grains of a body rain in through", kDemSourceKeys, kGuide,
     "### `[[dem.source]]`"},
    {"dem.wall_map", true, "the wall pressure and friction in bins over a wall's surface",
     particles::kWallMapKeys, kGuide, "### `[[dem.wall_map]]`"},
}};

} // namespace

std::span<const io::KeyTable> dem_key_tables() {
    return kTables;
}

} // namespace grainload::dem
