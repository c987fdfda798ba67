#include "fem/gmsh_reader.hpp"

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace grainload::fem {

namespace {

/// Line-oriented reader that knows its line number for error messages.
class MshLines {
  public:
    explicit MshLines(std::istream& in) : in_(in) {}
    std::istringstream next() {
        std::string line;
        if (!std::getline(in_, line)) {
            fail("unexpected end of file");
        }
        ++number_;
        return std::istringstream(line);
    }
    std::string next_word() {
        std::string word;
        next() >> word;
        return word;
    }
    bool find_section(std::string& name) {
        std::string line;
        while (std::getline(in_, line)) {
            ++number_;
            if (!line.empty() && line[0] == '$' && line.rfind("$End", 0) != 0) {
                name = line.substr(1);
                while (!name.empty() && (name.back() == '\r' || name.back() == ' ')) {
                    name.pop_back();
                }
                return true;
            }
        }
        return false;
    }
    [[noreturn]] void fail(const std::string& why) const {
        throw std::invalid_argument("Gmsh file line " + std::to_string(number_) + ": " + why);
    }

  private:
    std::istream& in_;
    int number_ = 0;
};

using EntityKey = std::pair<int, int>; // (dimension, entity tag)

struct MshContent {
    std::map<EntityKey, std::string> physical_names; // (dimension, physical tag) -> name
    std::map<EntityKey, std::vector<int>> entity_groups;
    std::map<long, Index> node_index;
    std::map<EntityKey, std::set<Index>> group_nodes;
    std::map<EntityKey, std::vector<Index>> group_elements;
};

void read_physical_names(MshLines& lines, MshContent& c) {
    int count = 0;
    lines.next() >> count;
    for (int i = 0; i < count; ++i) {
        auto line = lines.next();
        int dim = 0, tag = 0;
        std::string name;
        line >> dim >> tag;
        std::getline(line >> std::ws, name);
        if (name.size() >= 2 && name.front() == '"') {
            name = name.substr(1, name.find('"', 1) - 1);
        }
        c.physical_names[{dim, tag}] = name;
    }
}

void read_entities(MshLines& lines, MshContent& c) {
    int counts[4] = {0, 0, 0, 0};
    lines.next() >> counts[0] >> counts[1] >> counts[2] >> counts[3];
    for (int dim = 0; dim < 4; ++dim) {
        for (int i = 0; i < counts[dim]; ++i) {
            auto line = lines.next();
            int tag = 0;
            double box = 0.0;
            line >> tag;
            for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) {
                line >> box;
            }
            int physical_count = 0;
            line >> physical_count;
            for (int k = 0; k < physical_count; ++k) {
                int physical = 0;
                line >> physical;
                c.entity_groups[{dim, tag}].push_back(physical);
            }
            if (!line) {
                lines.fail("malformed $Entities record");
            }
        }
    }
}

void read_nodes(MshLines& lines, ShellMesh& mesh, MshContent& c) {
    std::size_t blocks = 0, total = 0;
    lines.next() >> blocks >> total;
    for (std::size_t b = 0; b < blocks; ++b) {
        int dim = 0, tag = 0, parametric = 0;
        std::size_t count = 0;
        lines.next() >> dim >> tag >> parametric >> count;
        std::vector<long> tags(count);
        for (auto& t : tags) {
            lines.next() >> t;
        }
        for (const long t : tags) {
            double x = 0.0, y = 0.0, z = 0.0;
            auto line = lines.next();
            if (!(line >> x >> y >> z)) {
                lines.fail("malformed node coordinates");
            }
            c.node_index[t] = mesh.add_node(Vec3(x, y, z));
        }
    }
}

void read_elements(MshLines& lines, double thickness, ShellMesh& mesh, MshContent& c) {
    std::size_t blocks = 0, total = 0;
    lines.next() >> blocks >> total;
    const std::map<int, int> node_counts = {{15, 1}, {1, 2}, {2, 3}, {3, 4}};
    for (std::size_t b = 0; b < blocks; ++b) {
        int dim = 0, tag = 0, type = 0;
        std::size_t count = 0;
        lines.next() >> dim >> tag >> type >> count;
        const auto known = node_counts.find(type);
        if (known == node_counts.end()) {
            lines.fail("element type " + std::to_string(type) +
                       " is not supported (points, 2-node lines, 3-node triangles, 4-node quads)");
        }
        const auto groups = c.entity_groups.find({dim, tag});
        for (std::size_t e = 0; e < count; ++e) {
            auto line = lines.next();
            long element_tag = 0;
            line >> element_tag;
            std::vector<Index> nodes;
            for (int k = 0; k < known->second; ++k) {
                long node_tag = 0;
                line >> node_tag;
                const auto it = c.node_index.find(node_tag);
                if (!line || it == c.node_index.end()) {
                    lines.fail("element " + std::to_string(element_tag) + ": unknown node id " +
                               std::to_string(node_tag));
                }
                nodes.push_back(it->second);
            }
            Index element = -1;
            if (type == 2 || type == 3) {
                element = mesh.add_element(
                    {nodes[0], nodes[1], nodes[2], type == 2 ? nodes[2] : nodes[3]}, thickness);
            }
            if (groups == c.entity_groups.end()) {
                continue;
            }
            for (const int physical : groups->second) {
                c.group_nodes[{dim, physical}].insert(nodes.begin(), nodes.end());
                if (element >= 0) {
                    c.group_elements[{dim, physical}].push_back(element);
                }
            }
        }
    }
}

} // namespace

ShellMesh read_gmsh(std::istream& in, double thickness) {
    MshLines lines(in);
    ShellMesh mesh;
    MshContent content;
    std::string section;
    bool has_format = false;
    while (lines.find_section(section)) {
        if (section == "MeshFormat") {
            std::string version;
            lines.next() >> version;
            if (version.rfind("4.1", 0) != 0) {
                lines.fail("MSH format " + version + " is not supported; export as 4.1 ASCII");
            }
            has_format = true;
        } else if (section == "PhysicalNames") {
            read_physical_names(lines, content);
        } else if (section == "Entities") {
            read_entities(lines, content);
        } else if (section == "Nodes") {
            read_nodes(lines, mesh, content);
        } else if (section == "Elements") {
            read_elements(lines, thickness, mesh, content);
        }
    }
    if (!has_format) {
        throw std::invalid_argument("not a Gmsh file: no $MeshFormat section");
    }
    for (const auto& [group, nodes] : content.group_nodes) {
        const auto named = content.physical_names.find(group);
        const std::string name = named != content.physical_names.end()
                                     ? named->second
                                     : "group" + std::to_string(group.second);
        mesh.add_node_set(name, std::vector<Index>(nodes.begin(), nodes.end()));
        const auto elements = content.group_elements.find(group);
        if (elements != content.group_elements.end()) {
            mesh.add_element_set(name, elements->second);
        }
    }
    return mesh;
}

ShellMesh read_gmsh_file(const std::string& path, double thickness) {
    std::ifstream in(path);
    if (!in) {
        throw std::invalid_argument("cannot open Gmsh file '" + path + "'");
    }
    return read_gmsh(in, thickness);
}

} // namespace grainload::fem
