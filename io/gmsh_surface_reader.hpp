#pragma once
// The surface of a Gmsh mesh file as a SurfaceMesh, for rigid walls and bodies.

#include "io/surface_mesh.hpp"

#include <string>

namespace grainload::io {

/// The surface of a Gmsh ASCII mesh, format 4.1 (parsed by read_gmsh_file_content, see
/// gmsh_file.hpp): 2-node lines, 3-node triangles and 4-node quadrangles in their node order;
/// points are dropped. It keeps no physical groups (fem/gmsh_reader turns those into sets): a
/// rigid wall or a body takes the whole file. Throws std::invalid_argument naming `name` and
/// the line.
SurfaceMesh read_gmsh_surface(const std::string& text, const std::string& name);

} // namespace grainload::io
