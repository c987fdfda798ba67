#pragma once
// The surface mesh of a case-file table: a .stl or .msh file, in its unit, scaled and offset.

#include "io/key_spec.hpp"
#include "io/surface_mesh.hpp"

#include <array>
#include <string>

namespace grainload::io {

class CaseTable;

/// The keys read_surface_mesh reads: a mesh wall's and a mesh body's surface (and, for a body
/// from an LS-DYNA deck, its `file`).
inline constexpr std::array<KeySpec, 4> kSurfaceMeshKeys{{
    {"file", "string", "required for a mesh",
     "relative to the case file: a surface mesh, .stl or .msh (a body: or an LS-DYNA deck)"},
    {"unit", "length unit", "m", "the length unit of the file's coordinates"},
    {"scale", "number", "1", "a factor on the coordinates", 1.0},
    {"offset", "length vector", "0 m", "added after scaling"},
}};

/// The mesh in `path`, by its extension (either case): .stl (ASCII or binary) or .msh (Gmsh
/// 4.1 ASCII). Coordinates as in the file. Throws std::invalid_argument naming the file (and
/// the line for text formats) when it cannot be read.
SurfaceMesh read_surface_mesh_file(const std::string& path);

/// The mesh of a case-file table with the keys `file` (relative to the case file), `unit`
/// (length unit of the file's coordinates, default "m"), `scale` (a factor, default 1) and
/// `offset` (a length vector added after scaling, default 0). Every face (segment in 2D) is
/// checked to have a non-zero area (length) and, in a 2D case, every vertex to lie in z = 0.
/// Errors throw CaseError located at the key `file` (or the key at fault).
SurfaceMesh read_surface_mesh(const CaseTable& table);

} // namespace grainload::io
