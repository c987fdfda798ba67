#include "io/gmsh_file.hpp"

#include <sstream>
#include <stdexcept>

namespace grainload::io {

namespace {

/// Reads the sections of one file, knowing its line number for error messages.
class GmshParser {
  public:
    GmshParser(std::istream& in, const std::string& name) : in_(in), name_(name) {}

    GmshFile read() {
        bool has_format = false;
        std::string section;
        while (next_section(section)) {
            if (section == "MeshFormat") {
                read_format();
                has_format = true;
            } else if (section == "PhysicalNames") {
                read_physical_names();
            } else if (section == "Entities") {
                read_entities();
            } else if (section == "Nodes") {
                read_nodes();
            } else if (section == "Elements") {
                read_elements();
            }
        }
        if (!has_format) {
            throw std::invalid_argument(name_ + ": not a Gmsh file: no $MeshFormat section");
        }
        return std::move(file_);
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

    void read_physical_names() {
        int count = 0;
        next_line() >> count;
        for (int i = 0; i < count; ++i) {
            auto line = next_line();
            int dimension = 0, tag = 0;
            std::string name;
            line >> dimension >> tag;
            std::getline(line >> std::ws, name);
            if (name.size() >= 2 && name.front() == '"') {
                name = name.substr(1, name.find('"', 1) - 1);
            }
            file_.physical_names[{dimension, tag}] = name;
        }
    }

    void read_entities() {
        int counts[4] = {0, 0, 0, 0};
        next_line() >> counts[0] >> counts[1] >> counts[2] >> counts[3];
        for (int dimension = 0; dimension < 4; ++dimension) {
            for (int i = 0; i < counts[dimension]; ++i) {
                auto line = next_line();
                int tag = 0;
                double box = 0.0;
                line >> tag;
                // A point has its coordinates, other entities their bounding box.
                for (int k = 0; k < (dimension == 0 ? 3 : 6); ++k) {
                    line >> box;
                }
                int physical_count = 0;
                line >> physical_count;
                // Each tag is read before the next is asked for: a count of 2e9 on a short
                // line would otherwise push zeros for minutes (a fuzzer's timeout).
                for (int k = 0; k < physical_count; ++k) {
                    int physical = 0;
                    if (!(line >> physical)) {
                        fail("malformed $Entities record: fewer physical tags than its count");
                    }
                    file_.entity_groups[{dimension, tag}].push_back(physical);
                }
                if (!line) {
                    fail("malformed $Entities record");
                }
            }
        }
    }

    void read_nodes() {
        std::size_t blocks = 0, total = 0;
        next_line() >> blocks >> total;
        for (std::size_t b = 0; b < blocks; ++b) {
            int dimension = 0, entity = 0, parametric = 0;
            std::size_t count = 0;
            if (!(next_line() >> dimension >> entity >> parametric >> count)) {
                fail("malformed $Nodes block header");
            }
            // Tags are read one line each, not allocated from the header's count first: a
            // count of 3e15 in a damaged file would ask for petabytes before the end of file
            // (fuzz_gmsh); this way the file runs out first, with its line number.
            std::vector<long> tags;
            for (std::size_t k = 0; k < count; ++k) {
                long tag = 0;
                next_line() >> tag;
                tags.push_back(tag);
            }
            // Parametric coordinates, when present, follow x y z on the same line.
            for (const long tag : tags) {
                double x = 0.0, y = 0.0, z = 0.0;
                if (!(next_line() >> x >> y >> z)) {
                    fail("malformed node coordinates");
                }
                node_index_[tag] = static_cast<Index>(file_.nodes.size());
                file_.nodes.emplace_back(x, y, z);
            }
        }
    }

    void read_elements() {
        std::size_t blocks = 0, total = 0;
        next_line() >> blocks >> total;
        const std::map<int, int> node_counts = {{15, 1}, {1, 2}, {2, 3}, {3, 4}};
        for (std::size_t b = 0; b < blocks; ++b) {
            GmshElement element;
            int type = 0;
            std::size_t count = 0;
            next_line() >> element.dimension >> element.entity >> type >> count;
            const auto known = node_counts.find(type);
            if (known == node_counts.end()) {
                fail("element type " + std::to_string(type) +
                     " is not supported: expected first-order points (15), lines (1), "
                     "triangles (2) or quadrangles (3); export with element order 1");
            }
            element.node_count = known->second;
            for (std::size_t e = 0; e < count; ++e) {
                read_element_nodes(next_line(), element);
                file_.elements.push_back(element);
            }
        }
    }

    void read_element_nodes(std::istringstream line, GmshElement& element) {
        long element_tag = 0;
        line >> element_tag;
        for (int k = 0; k < element.node_count; ++k) {
            long tag = 0;
            line >> tag;
            const auto it = node_index_.find(tag);
            if (!line || it == node_index_.end()) {
                fail("element " + std::to_string(element_tag) + ": unknown node id " +
                     std::to_string(tag));
            }
            element.nodes[static_cast<std::size_t>(k)] = it->second;
        }
    }

    [[noreturn]] void fail(const std::string& why) const {
        throw std::invalid_argument(name_ + ":" + std::to_string(line_number_) + ": " + why);
    }

    std::istream& in_;
    std::string name_;
    GmshFile file_;
    std::map<long, Index> node_index_;
    int line_number_ = 0;
};

} // namespace

GmshFile read_gmsh_file_content(std::istream& in, const std::string& name) {
    return GmshParser(in, name).read();
}

} // namespace grainload::io
