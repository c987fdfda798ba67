#include "fem/gmsh_reader.hpp"

#include "io/gmsh_file.hpp"

#include <algorithm>
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

/// Thickness of each surface entity in a group of `by_group` (entities in none: absent).
std::map<int, double> entity_thickness(const io::GmshFile& file, const std::string& name,
                                       const GroupThickness& by_group) {
    std::map<std::string, int> surface_groups; // physical surface name -> tag
    for (const auto& [group, group_name] : file.physical_names) {
        if (group.first == 2) {
            surface_groups[group_name] = group.second;
        }
    }
    std::map<int, double> thickness;
    for (const auto& [group_name, t] : by_group) {
        const auto tag = surface_groups.find(group_name);
        if (tag == surface_groups.end()) {
            std::string known;
            for (const auto& [surface, ignored] : surface_groups) {
                known += (known.empty() ? "" : ", ") + surface;
            }
            throw std::invalid_argument(
                name + ": no physical surface named \"" + group_name +
                "\" (physical surfaces: " + (known.empty() ? "none" : known) + ")");
        }
        for (const auto& [entity, groups] : file.entity_groups) {
            if (entity.first != 2 ||
                std::find(groups.begin(), groups.end(), tag->second) == groups.end()) {
                continue;
            }
            const auto [it, fresh] = thickness.emplace(entity.second, t);
            if (!fresh && it->second != t) {
                throw std::invalid_argument(name + ": surface " + std::to_string(entity.second) +
                                            " lies in two groups with different thicknesses, "
                                            "one of them \"" +
                                            group_name + "\"");
            }
        }
    }
    return thickness;
}

ShellMesh read_named_gmsh(std::istream& in, const std::string& name, double thickness,
                          const GroupThickness& by_group) {
    const io::GmshFile file = io::read_gmsh_file_content(in, name);
    const std::map<int, double> listed = entity_thickness(file, name, by_group);
    ShellMesh mesh;
    for (const Vec3& x : file.nodes) {
        mesh.add_node(x);
    }
    // The shell element made of each file element (-1: a point or a line).
    std::vector<Index> shell_element(file.elements.size(), -1);
    for (std::size_t e = 0; e < file.elements.size(); ++e) {
        const io::GmshElement& element = file.elements[e];
        if (element.node_count < 3) {
            continue;
        }
        const auto found = listed.find(element.entity);
        const double t = found != listed.end() ? found->second : thickness;
        if (!(t > 0.0)) {
            throw std::invalid_argument(name + ": surface " + std::to_string(element.entity) +
                                        " is in no physical group with a thickness, and no "
                                        "default thickness is given");
        }
        const auto& n = element.nodes;
        shell_element[e] =
            mesh.add_element({n[0], n[1], n[2], element.node_count == 3 ? n[2] : n[3]}, t);
    }
    add_physical_groups(file, shell_element, mesh);
    return mesh;
}

} // namespace

ShellMesh read_gmsh(std::istream& in, double thickness, const GroupThickness& by_group) {
    return read_named_gmsh(in, "Gmsh file", thickness, by_group);
}

ShellMesh read_gmsh_file(const std::string& path, double thickness,
                         const GroupThickness& by_group) {
    std::ifstream in(path);
    if (!in) {
        throw std::invalid_argument("cannot open Gmsh file '" + path + "'");
    }
    return read_named_gmsh(in, path, thickness, by_group);
}

} // namespace grainload::fem
