#pragma once
// Shell meshes read from Gmsh files: shell elements, named sets, thickness per group.

#include "fem/shell_mesh.hpp"

#include <istream>
#include <map>
#include <string>

namespace grainload::fem {

/// Thickness [m] of the elements of named physical surfaces (a wagon's walls, doors, ...).
using GroupThickness = std::map<std::string, double>;

/// Reads a Gmsh ASCII mesh, format 4.1 (parsed by io::read_gmsh_file_content): 3-node
/// triangles (as collapsed quads) and 4-node quadrilaterals become shell elements; every
/// physical group becomes a node set (the nodes of its elements, any dimension) and, for
/// surfaces, an element set, under its name (or "group<tag>"). An element takes the thickness
/// of the physical surface it belongs to in `by_group`, else `thickness` (0: none given, and
/// every element must then be in a listed group). A listed name that is no physical surface, or
/// an element in two listed groups, is refused. Throws std::invalid_argument naming the file
/// (or "Gmsh file" for a stream) and the line or element.
ShellMesh read_gmsh(std::istream& in, double thickness, const GroupThickness& by_group = {});
ShellMesh read_gmsh_file(const std::string& path, double thickness,
                         const GroupThickness& by_group = {});

} // namespace grainload::fem
