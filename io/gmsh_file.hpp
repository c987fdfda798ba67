#pragma once
// The content of a Gmsh ASCII mesh, format 4.1: nodes, first-order elements, physical groups.

#include "io/types.hpp"

#include <array>
#include <istream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace grainload::io {

/// One first-order element of a Gmsh file: a point (1 node), line (2), triangle (3) or
/// quadrangle (4), with the entity it belongs to.
struct GmshElement {
    int dimension = 0; ///< of its entity: 0 point, 1 curve, 2 surface
    int entity = 0;    ///< entity tag
    int node_count = 0;
    std::array<Index, 4> nodes{}; ///< indices into GmshFile::nodes, in the file's node order
};

/// The content of a Gmsh ASCII mesh, format 4.1, that grainload uses: nodes, first-order
/// elements in file order, and physical groups.
struct GmshFile {
    using Key = std::pair<int, int>; ///< (dimension, tag)
    std::vector<Vec3> nodes;
    std::vector<GmshElement> elements;
    std::map<Key, std::vector<int>> entity_groups; ///< (dimension, entity) -> physical tags
    std::map<Key, std::string> physical_names;     ///< (dimension, physical tag) -> name
};

/// Parses a Gmsh ASCII mesh, format 4.1 (gmsh.info, "MSH file format": sections $MeshFormat,
/// $PhysicalNames, $Entities, $Nodes, $Elements; others are skipped). Element types 15
/// (point), 1 (2-node line), 2 (3-node triangle) and 3 (4-node quadrangle) are kept; any other
/// type, a binary file or another version is refused. Throws std::invalid_argument with
/// "<name>:<line>: <why>".
GmshFile read_gmsh_file_content(std::istream& in, const std::string& name);

} // namespace grainload::io
