#include "io/surface_mesh_reader.hpp"

#include "io/case_table.hpp"
#include "io/gmsh_surface_reader.hpp"
#include "io/stl_reader.hpp"
#include "io/units.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace grainload::io {

namespace {

std::string lower_extension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

double length_unit(const CaseTable& table) {
    const std::string text = table.string_or("unit", default_text(kSurfaceMeshKeys, "unit"));
    std::string error;
    const auto unit = parse_unit(text, &error);
    if (!unit || unit->dimension != dimension::kLength) {
        table.fail("unit", "expected a length unit for the mesh coordinates (\"m\", \"mm\"), "
                           "got \"" +
                               text + "\"");
    }
    return unit->value;
}

/// Faces of zero area would give no normal (walls) and no crossing (fills): a mesh
/// exporter's slip, so it is refused rather than skipped. "Zero" is relative to the face's
/// own longest edge: area below 1e-12 L^2 (a sliver of height 2e-12 L).
void check_faces(const CaseTable& table, const SurfaceMesh& mesh) {
    const auto& x = mesh.vertices;
    const auto refuse = [&](const std::string& kind, std::size_t index) {
        table.fail("file", kind + " " + std::to_string(index + 1) +
                               " of the mesh is degenerate (zero area or length)");
    };
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const auto& [a, b, c] = mesh.triangles[f];
        const Vec3 ab = x[b] - x[a], ac = x[c] - x[a], bc = x[c] - x[b];
        const double longest = std::max({ab.squaredNorm(), ac.squaredNorm(), bc.squaredNorm()});
        if (!(0.5 * ab.cross(ac).norm() > 1e-12 * longest)) {
            refuse("triangle", f);
        }
    }
    for (std::size_t f = 0; f < mesh.quads.size(); ++f) {
        const auto& [a, b, c, d] = mesh.quads[f];
        const Vec3 ac = x[c] - x[a], bd = x[d] - x[b];
        const double longest = std::max(ac.squaredNorm(), bd.squaredNorm());
        if (!(0.5 * ac.cross(bd).norm() > 1e-12 * longest)) {
            refuse("quadrangle", f);
        }
    }
    for (std::size_t s = 0; s < mesh.segments.size(); ++s) {
        const auto& [a, b] = mesh.segments[s];
        if (!((x[b] - x[a]).norm() > 0.0)) {
            refuse("line", s);
        }
    }
}

void check_plane(const CaseTable& table, const SurfaceMesh& mesh) {
    double extent = 0.0, off_plane = 0.0;
    for (const Vec3& v : mesh.vertices) {
        extent = std::max(extent, v.head<2>().cwiseAbs().maxCoeff());
        off_plane = std::max(off_plane, std::abs(v.z()));
    }
    if (off_plane > 1e-9 * extent) {
        table.fail("file", "a plane-strain (dimension = 2) mesh must lie in z = 0; a vertex has "
                           "z = " +
                               std::to_string(off_plane) + " m");
    }
}

} // namespace

SurfaceMesh read_surface_mesh_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw std::invalid_argument(path + ": cannot open the mesh file");
    }
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string extension = lower_extension(path);
    if (extension == ".stl") {
        return read_stl(bytes, path);
    }
    if (extension == ".msh") {
        return read_gmsh_surface(bytes, path);
    }
    throw std::invalid_argument(path + ": unknown mesh format \"" + extension +
                                "\"; expected .stl (ASCII or binary) or .msh (Gmsh 4.1 ASCII)");
}

SurfaceMesh read_surface_mesh(const CaseTable& table) {
    const std::string path = table.file_path("file");
    SurfaceMesh mesh;
    try {
        mesh = read_surface_mesh_file(path);
    } catch (const std::invalid_argument& error) {
        table.fail("file", error.what());
    }
    const double factor =
        length_unit(table) * table.number_or("scale", default_value(kSurfaceMeshKeys, "scale"));
    if (!(factor > 0.0)) {
        table.fail("scale", "expected a positive scale factor");
    }
    const Vec3 offset =
        table.vector_or("offset", dimension::kLength, default_vector(kSurfaceMeshKeys, "offset"));
    for (Vec3& v : mesh.vertices) {
        v = factor * v + offset;
    }
    check_faces(table, mesh);
    if (table.spatial_dimension() == 2) {
        check_plane(table, mesh);
    }
    return mesh;
}

} // namespace grainload::io
