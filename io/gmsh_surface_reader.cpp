#include "io/gmsh_surface_reader.hpp"

#include "io/gmsh_file.hpp"

#include <sstream>

namespace grainload::io {

SurfaceMesh read_gmsh_surface(const std::string& text, const std::string& name) {
    std::istringstream in(text);
    GmshFile file = read_gmsh_file_content(in, name);
    SurfaceMesh mesh;
    mesh.vertices = std::move(file.nodes);
    for (const GmshElement& element : file.elements) {
        const auto& n = element.nodes;
        if (element.node_count == 2) {
            mesh.segments.push_back({n[0], n[1]});
        } else if (element.node_count == 3) {
            mesh.triangles.push_back({n[0], n[1], n[2]});
        } else if (element.node_count == 4) {
            mesh.quads.push_back(n);
        }
    }
    return mesh;
}

} // namespace grainload::io
