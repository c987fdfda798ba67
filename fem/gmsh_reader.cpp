#include "fem/gmsh_reader.hpp"

#include "io/gmsh_file.hpp"

#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

namespace grainload::fem {

namespace {

/// Every physical group becomes a node set (the nodes of its elements, any dimension) and,
/// when it holds shell elements, an element set, under its name or "group<tag>".
void add_physical_groups(const io::GmshFile& file, const std::vector<Index>& shell_element,
                         ShellMesh& mesh) {
    std::map<io::GmshFile::Key, std::set<Index>> group_nodes;
    std::map<io::GmshFile::Key, std::vector<Index>> group_elements;
    for (std::size_t e = 0; e < file.elements.size(); ++e) {
        const io::GmshElement& element = file.elements[e];
        const auto groups = file.entity_groups.find({element.dimension, element.entity});
        if (groups == file.entity_groups.end()) {
            continue;
        }
        for (const int physical : groups->second) {
            const io::GmshFile::Key group{element.dimension, physical};
            group_nodes[group].insert(element.nodes.begin(),
                                      element.nodes.begin() + element.node_count);
            if (shell_element[e] >= 0) {
                group_elements[group].push_back(shell_element[e]);
            }
        }
    }
    for (const auto& [group, nodes] : group_nodes) {
        const auto named = file.physical_names.find(group);
        const std::string name = named != file.physical_names.end()
                                     ? named->second
                                     : "group" + std::to_string(group.second);
        mesh.add_node_set(name, std::vector<Index>(nodes.begin(), nodes.end()));
        const auto elements = group_elements.find(group);
        if (elements != group_elements.end()) {
            mesh.add_element_set(name, elements->second);
        }
    }
}

ShellMesh read_named_gmsh(std::istream& in, const std::string& name, double thickness) {
    const io::GmshFile file = io::read_gmsh_file_content(in, name);
    ShellMesh mesh;
    for (const Vec3& x : file.nodes) {
        mesh.add_node(x);
    }
    // The shell element made of each file element (-1: a point or a line).
    std::vector<Index> shell_element(file.elements.size(), -1);
    for (std::size_t e = 0; e < file.elements.size(); ++e) {
        const auto& n = file.elements[e].nodes;
        if (file.elements[e].node_count == 3) {
            shell_element[e] = mesh.add_element({n[0], n[1], n[2], n[2]}, thickness);
        } else if (file.elements[e].node_count == 4) {
            shell_element[e] = mesh.add_element({n[0], n[1], n[2], n[3]}, thickness);
        }
    }
    add_physical_groups(file, shell_element, mesh);
    return mesh;
}

} // namespace

ShellMesh read_gmsh(std::istream& in, double thickness) {
    return read_named_gmsh(in, "Gmsh file", thickness);
}

ShellMesh read_gmsh_file(const std::string& path, double thickness) {
    std::ifstream in(path);
    if (!in) {
        throw std::invalid_argument("cannot open Gmsh file '" + path + "'");
    }
    return read_named_gmsh(in, path, thickness);
}

} // namespace grainload::fem
