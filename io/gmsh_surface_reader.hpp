#pragma once

#include "io/surface_mesh.hpp"

#include <string>

namespace grainload::io {

/// The surface of a Gmsh ASCII mesh, format 4.1 (gmsh.info, "MSH file format", sections
/// $MeshFormat, $Nodes, $Elements; others are skipped): 2-node lines (type 1), 3-node
/// triangles (type 2) and 4-node quadrangles (type 3), in their node order; points (type 15)
/// are skipped and any other type is refused. Unlike fem/gmsh_reader (shell elements with
/// physical groups) it keeps no groups: a rigid wall or a body takes the whole file.
/// Throws std::invalid_argument naming `name` and the line.
SurfaceMesh read_gmsh_surface(const std::string& text, const std::string& name);

} // namespace grainload::io
