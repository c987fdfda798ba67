#pragma once

#include "fem/shell_mesh.hpp"

#include <istream>
#include <string>

namespace grainload::fem {

/// Reads a Gmsh ASCII mesh, format 4.1 (parsed by io::read_gmsh_file_content): 3-node
/// triangles (as collapsed quads) and 4-node quadrilaterals become shell elements of the given
/// thickness; every physical group becomes a node set (the nodes of its elements, any
/// dimension) and, for surfaces, an element set, under its name (or "group<tag>").
/// Throws std::invalid_argument naming the file (or "Gmsh file" for a stream) and the line.
ShellMesh read_gmsh(std::istream& in, double thickness);
ShellMesh read_gmsh_file(const std::string& path, double thickness);

} // namespace grainload::fem
