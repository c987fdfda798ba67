#include "io/stl_reader.hpp"

#include <bit>
#include <cstdint>
#include <map>
#include <sstream>
#include <stdexcept>

namespace grainload::io {

namespace {

/// Merges vertices with bit-identical coordinates: an STL writer prints a shared corner the
/// same way in every triangle that uses it, and the closedness check needs shared vertices.
class VertexWelder {
  public:
    explicit VertexWelder(SurfaceMesh& mesh) : mesh_(mesh) {}
    Index add(const Vec3& x) {
        const auto [it, inserted] =
            index_.try_emplace({x.x(), x.y(), x.z()}, static_cast<Index>(mesh_.vertices.size()));
        if (inserted) {
            mesh_.vertices.push_back(x);
        }
        return it->second;
    }

  private:
    SurfaceMesh& mesh_;
    std::map<std::array<double, 3>, Index> index_;
};

float little_endian_float(const std::string& bytes, std::size_t at) {
    std::uint32_t word = 0;
    for (std::size_t k = 0; k < 4; ++k) {
        word |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + k])) << (8 * k);
    }
    return std::bit_cast<float>(word);
}

std::uint32_t little_endian_count(const std::string& bytes) {
    std::uint32_t count = 0;
    for (std::size_t k = 0; k < 4; ++k) {
        count |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[80 + k])) << (8 * k);
    }
    return count;
}

bool is_binary(const std::string& bytes) {
    return bytes.size() >= 84 && bytes.size() == 84 + 50 * std::size_t{little_endian_count(bytes)};
}

SurfaceMesh read_binary(const std::string& bytes) {
    SurfaceMesh mesh;
    VertexWelder welder(mesh);
    const std::uint32_t count = little_endian_count(bytes);
    for (std::size_t t = 0; t < count; ++t) {
        // Each record: normal (3 floats), three vertices (9 floats), 2 attribute bytes.
        const std::size_t record = 84 + 50 * t;
        std::array<Index, 3> face{};
        for (std::size_t v = 0; v < 3; ++v) {
            const std::size_t at = record + 12 + 12 * v;
            face[v] =
                welder.add(Vec3(little_endian_float(bytes, at), little_endian_float(bytes, at + 4),
                                little_endian_float(bytes, at + 8)));
        }
        mesh.triangles.push_back(face);
    }
    return mesh;
}

/// ASCII STL, read line by line: solid / facet / outer loop / 3 x vertex / endloop /
/// endfacet / endsolid; several solids in one file are merged.
class AsciiStl {
  public:
    AsciiStl(const std::string& bytes, const std::string& name) : in_(bytes), name_(name) {}

    SurfaceMesh read() {
        VertexWelder welder(mesh_);
        std::string line;
        std::vector<Index> loop;
        while (std::getline(in_, line)) {
            ++line_number_;
            std::istringstream words(line);
            std::string keyword;
            if (!(words >> keyword) || keyword == "solid" || keyword == "facet" ||
                keyword == "outer" || keyword == "endsolid") {
                continue;
            }
            if (keyword == "vertex") {
                double x = 0.0, y = 0.0, z = 0.0;
                if (!(words >> x >> y >> z)) {
                    fail("expected three coordinates after 'vertex'");
                }
                loop.push_back(welder.add(Vec3(x, y, z)));
            } else if (keyword == "endloop") {
                if (loop.size() != 3) {
                    fail("a facet has " + std::to_string(loop.size()) +
                         " vertices; STL facets are triangles (3)");
                }
                mesh_.triangles.push_back({loop[0], loop[1], loop[2]});
                loop.clear();
            } else if (keyword != "endfacet") {
                fail("unexpected '" + keyword + "' in an ASCII STL file");
            }
        }
        return std::move(mesh_);
    }

  private:
    [[noreturn]] void fail(const std::string& why) const {
        throw std::invalid_argument(name_ + ":" + std::to_string(line_number_) + ": " + why);
    }

    std::istringstream in_;
    std::string name_;
    SurfaceMesh mesh_;
    int line_number_ = 0;
};

} // namespace

SurfaceMesh read_stl(const std::string& bytes, const std::string& name) {
    if (is_binary(bytes)) {
        return read_binary(bytes);
    }
    const auto start = bytes.find_first_not_of(" \t\r\n");
    if (start == std::string::npos || bytes.compare(start, 5, "solid") != 0) {
        throw std::invalid_argument(name + ": not an STL file: neither ASCII (starting with "
                                           "'solid') nor binary (84 + 50 n bytes for n "
                                           "triangles)");
    }
    return AsciiStl(bytes, name).read();
}

} // namespace grainload::io
