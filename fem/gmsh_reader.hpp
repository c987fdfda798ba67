#pragma once

#include "fem/shell_mesh.hpp"

#include <istream>
#include <string>

namespace grainload::fem {

/// Reads a Gmsh ASCII mesh, format 4.1 (gmsh.info, "MSH file format"): 3-node triangles
/// (type 2, as collapsed quads) and 4-node quadrilaterals (type 3) become shell elements of
/// the given thickness; every physical group becomes a node set (the nodes of its elements,
/// any dimension) and, for surfaces, an element set, under its name (or "group<tag>").
/// Throws std::invalid_argument naming the line for malformed input.
ShellMesh read_gmsh(std::istream& in, double thickness);
ShellMesh read_gmsh_file(const std::string& path, double thickness);

} // namespace grainload::fem
