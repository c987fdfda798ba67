#include "fem/shell_mesh_generators.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <stdexcept>

namespace grainload::fem {

namespace {

/// Maps the unit square (a, b) in [0,1]^2 onto the surface.
using SurfaceMap = std::function<Vec3(double a, double b)>;

struct EdgeNames {
    const char* a0;
    const char* a1;
    const char* b0;
    const char* b1;
};

/// Exact unit normal d(map)/da x d(map)/db by central differences (one-sided at the edges);
/// the step is far below the element size, so the error is round-off level.
Vec3 surface_normal(const SurfaceMap& map, double a, double b) {
    constexpr double h = 1e-6;
    const double a0 = std::max(a - h, 0.0), a1 = std::min(a + h, 1.0);
    const double b0 = std::max(b - h, 0.0), b1 = std::min(b + h, 1.0);
    const Vec3 da = (map(a1, b) - map(a0, b)) / (a1 - a0);
    const Vec3 db = (map(a, b1) - map(a, b0)) / (b1 - b0);
    return da.cross(db).normalized();
}

ShellMesh structured(const SurfaceMap& map, int na, int nb, double thickness,
                     const EdgeNames& names) {
    if (na < 1 || nb < 1) {
        throw std::invalid_argument("mesh generator: element counts must be >= 1");
    }
    ShellMesh mesh;
    const auto id = [nb](int i, int j) { return static_cast<Index>(i) * (nb + 1) + j; };
    std::vector<Index> a0, a1, b0, b1;
    std::vector<Vec3> normals;
    for (int i = 0; i <= na; ++i) {
        for (int j = 0; j <= nb; ++j) {
            const double a = double(i) / na;
            const double b = double(j) / nb;
            const Index n = mesh.add_node(map(a, b));
            normals.push_back(surface_normal(map, a, b));
            if (i == 0)
                a0.push_back(n);
            if (i == na)
                a1.push_back(n);
            if (j == 0)
                b0.push_back(n);
            if (j == nb)
                b1.push_back(n);
        }
    }
    for (int i = 0; i < na; ++i) {
        for (int j = 0; j < nb; ++j) {
            mesh.add_element({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}, thickness);
        }
    }
    mesh.set_nodal_normals(std::move(normals));
    std::vector<Index> all_nodes(static_cast<std::size_t>(mesh.node_count()));
    std::iota(all_nodes.begin(), all_nodes.end(), Index{0});
    std::vector<Index> all_elements(static_cast<std::size_t>(mesh.element_count()));
    std::iota(all_elements.begin(), all_elements.end(), Index{0});
    mesh.add_node_set("all", std::move(all_nodes));
    mesh.add_element_set("all", std::move(all_elements));
    mesh.add_node_set(names.a0, std::move(a0));
    mesh.add_node_set(names.a1, std::move(a1));
    mesh.add_node_set(names.b0, std::move(b0));
    mesh.add_node_set(names.b1, std::move(b1));
    return mesh;
}

} // namespace

ShellMesh make_plate(double lx, double ly, int nx, int ny, double thickness) {
    return structured([=](double a, double b) { return Vec3(a * lx, b * ly, 0.0); }, nx, ny,
                      thickness, {"x0", "x1", "y0", "y1"});
}

ShellMesh make_cylinder(double radius, double length, double phi0, double phi1, int n_phi, int n_y,
                        double thickness) {
    const auto map = [=](double a, double b) {
        const double phi = phi0 + a * (phi1 - phi0);
        return Vec3(radius * std::sin(phi), b * length, radius * std::cos(phi));
    };
    return structured(map, n_phi, n_y, thickness, {"phi0", "phi1", "y0", "y1"});
}

ShellMesh make_sphere_zone(double radius, double polar0, double polar1, double azimuth1,
                           int n_polar, int n_azimuth, double thickness) {
    const auto map = [=](double a, double b) {
        const double polar = polar0 + a * (polar1 - polar0);
        const double azimuth = b * azimuth1;
        return Vec3(radius * std::sin(polar) * std::cos(azimuth),
                    radius * std::sin(polar) * std::sin(azimuth), radius * std::cos(polar));
    };
    return structured(map, n_polar, n_azimuth, thickness,
                      {"polar0", "polar1", "azimuth0", "azimuth1"});
}

ShellMesh make_cone(double r0, double r1, double height, double azimuth1, int n_azimuth,
                    int n_height, double thickness) {
    const auto map = [=](double a, double b) {
        const double azimuth = a * azimuth1;
        const double r = r0 + b * (r1 - r0);
        return Vec3(r * std::cos(azimuth), r * std::sin(azimuth), b * height);
    };
    return structured(map, n_azimuth, n_height, thickness, {"azimuth0", "azimuth1", "z0", "z1"});
}

} // namespace grainload::fem
