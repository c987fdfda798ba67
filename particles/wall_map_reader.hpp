#pragma once
// The wall-load map tables of a case ([[sph.wall_map]], [[dem.wall_map]]), read into maps.

#include "io/key_spec.hpp"
#include "particles/wall_map.hpp"

#include <array>
#include <span>
#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::particles {

/// The keys of each [[sph.wall_map]] and [[dem.wall_map]] table (docs/user-guide/sph.md,
/// "Wall-load maps").
inline constexpr std::array<io::KeySpec, 14> kWallMapKeys{{
    {"name", "string", "", "names the map's files, wall_maps/NAME_*.csv, and its summary figures"},
    {"walls", "string or list of strings", "",
     "the walls whose loads are mapped, by name: the method's walls (SPH: coupled shell "
     "interfaces too)"},
    {"type", "`cylinder` or `plane`", "",
     "cylinder: the unrolled wall, axial position by angle; plane: a grid on a parallelogram"},
    {"origin", "length vector", "",
     "cylinder: the point of the axis where the axial coordinate is 0; plane: a corner"},
    {"axis", "vector", "required for a cylinder", "the axis; the axial coordinate grows along it"},
    {"reference", "vector", "a normal to the axis",
     "cylinder: the direction of angle 0; the angle turns right-handed about the axis"},
    {"radius", "length", "required for a cylinder", "the wall's radius, for the cells' areas"},
    {"length", "length", "required for a cylinder", "the mapped length along the axis"},
    {"angles", "two angles", "0 360 deg", "cylinder: the mapped arc (a quarter model: 0 90 deg)"},
    {"edge_u", "length vector", "required for a plane", "the grid's first edge from origin"},
    {"edge_v", "length vector", "required for a plane in 3D",
     "the grid's second edge; in plane strain the grid is edge_u by 1 m of depth"},
    {"bins", "two integers", "",
     "cells along the axis and around it (cylinder) or along edge_u and edge_v (plane; in "
     "plane strain [n, 1])"},
    {"reach", "length", "no limit",
     "only loads this near the mapped surface count (one face of a box wall)"},
    {"window", "two times", "the whole run",
     "the interval whose mean and maximum maps go into wall_maps/NAME_window.csv"},
}};

/// The [[wall_map]] tables of `parent` (the [sph] or [dem] table); wall names resolve against
/// `wall_names` (their indices are the maps' walls). Each wall's patch half-width is 0 (a
/// point load): a method whose loads stand for patches sets its own.
std::vector<WallMapSet::Map> read_wall_maps(const io::CaseTable& parent,
                                            std::span<const std::string> wall_names, int dimension);

} // namespace grainload::particles
