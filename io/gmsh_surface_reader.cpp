#include "io/gmsh_surface_reader.hpp"

#include <map>
#include <sstream>
#include <stdexcept>

namespace grainload::io {

namespace {

class MshSurface {
  public:
    MshSurface(const std::string& text, const std::string& name) : in_(text), name_(name) {}

    SurfaceMesh read() {
        bool has_format = false;
        std::string section;
        while (next_section(section)) {
            if (section == "MeshFormat") {
                read_format();
                has_format = true;
            } else if (section == "Nodes") {
                read_nodes();
            } else if (section == "Elements") {
                read_elements();
            }
        }
        if (!has_format) {
            throw std::invalid_argument(name_ + ": not a Gmsh file: no $MeshFormat section");
        }
        return std::move(mesh_);
    }

  private:
    std::istringstream next_line() {
        std::string line;
        if (!std::getline(in_, line)) {
            fail("unexpected end of file");
        }
        ++line_number_;
        return std::istringstream(line);
    }

    bool next_section(std::string& name) {
        std::string line;
        while (std::getline(in_, line)) {
            ++line_number_;
            if (line.starts_with('$') && !line.starts_with("$End")) {
                name = line.substr(1, line.find_last_not_of(" \r"));
                return true;
            }
        }
        return false;
    }

    void read_format() {
        std::string version;
        int file_type = -1;
        next_line() >> version >> file_type;
        if (!version.starts_with("4.1") || file_type != 0) {
            fail("MSH format " + version + (file_type == 0 ? "" : " binary") +
                 " is not supported; export as version 4.1 ASCII");
        }
    }

    void read_nodes() {
        std::size_t blocks = 0, total = 0;
        next_line() >> blocks >> total;
        for (std::size_t b = 0; b < blocks; ++b) {
            int entity_dim = 0, entity_tag = 0, parametric = 0;
            std::size_t count = 0;
            if (!(next_line() >> entity_dim >> entity_tag >> parametric >> count)) {
                fail("malformed $Nodes block header");
            }
            std::vector<long> tags(count);
            for (auto& tag : tags) {
                next_line() >> tag;
            }
            // Parametric coordinates, when present, follow x y z on the same line.
            for (const long tag : tags) {
                double x = 0.0, y = 0.0, z = 0.0;
                if (!(next_line() >> x >> y >> z)) {
                    fail("malformed node coordinates");
                }
                node_index_[tag] = static_cast<Index>(mesh_.vertices.size());
                mesh_.vertices.emplace_back(x, y, z);
            }
        }
    }

    void read_elements() {
        std::size_t blocks = 0, total = 0;
        next_line() >> blocks >> total;
        const std::map<int, int> node_counts = {{15, 1}, {1, 2}, {2, 3}, {3, 4}};
        for (std::size_t b = 0; b < blocks; ++b) {
            int entity_dim = 0, entity_tag = 0, type = 0;
            std::size_t count = 0;
            next_line() >> entity_dim >> entity_tag >> type >> count;
            const auto known = node_counts.find(type);
            if (known == node_counts.end()) {
                fail("element type " + std::to_string(type) +
                     " is not supported: expected first-order lines (1), triangles (2) or "
                     "quadrangles (3); export the surface only, with element order 1");
            }
            for (std::size_t e = 0; e < count; ++e) {
                add_element(next_line(), known->second);
            }
        }
    }

    void add_element(std::istringstream line, int node_count) {
        long element_tag = 0;
        line >> element_tag;
        std::array<Index, 4> nodes{};
        for (int k = 0; k < node_count; ++k) {
            long tag = 0;
            line >> tag;
            const auto it = node_index_.find(tag);
            if (!line || it == node_index_.end()) {
                fail("element " + std::to_string(element_tag) + ": unknown node " +
                     std::to_string(tag));
            }
            nodes[static_cast<std::size_t>(k)] = it->second;
        }
        if (node_count == 2) {
            mesh_.segments.push_back({nodes[0], nodes[1]});
        } else if (node_count == 3) {
            mesh_.triangles.push_back({nodes[0], nodes[1], nodes[2]});
        } else if (node_count == 4) {
            mesh_.quads.push_back(nodes);
        }
    }

    [[noreturn]] void fail(const std::string& why) const {
        throw std::invalid_argument(name_ + ":" + std::to_string(line_number_) + ": " + why);
    }

    std::istringstream in_;
    std::string name_;
    SurfaceMesh mesh_;
    std::map<long, Index> node_index_;
    int line_number_ = 0;
};

} // namespace

SurfaceMesh read_gmsh_surface(const std::string& text, const std::string& name) {
    return MshSurface(text, name).read();
}

} // namespace grainload::io
