#include "fem/shell_mesh_generators.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <string_view>

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

/// One face of a box: the grid axis it is normal to, at index 0 or at the far end, and the two
/// grid axes (u, v) along which its quads run; u x v is the outward normal.
struct BoxFace {
    const char* name;
    int normal_axis;
    bool far_side;
    int u;
    int v;
};

constexpr std::array<BoxFace, 6> kBoxFaces = {{{"bottom", 2, false, 1, 0},
                                               {"top", 2, true, 0, 1},
                                               {"x0", 0, false, 2, 1},
                                               {"x1", 0, true, 1, 2},
                                               {"y0", 1, false, 0, 2},
                                               {"y1", 1, true, 2, 0}}};

using GridIndex = std::array<int, 3>;

/// Element counts along x, y, z and the grid spacing of a box.
struct BoxGrid {
    std::array<int, 3> n;
    Vec3 spacing;
};

/// The quads of one face; nodes are created on first use, so the faces share their edges
/// (`ids`: one node per grid point).
std::vector<Index> add_box_face(ShellMesh& mesh, std::map<GridIndex, Index>& ids,
                                const BoxGrid& grid, const BoxFace& face, double thickness) {
    const auto axis = [](int a) { return static_cast<std::size_t>(a); };
    const auto node = [&](int p, int q) {
        GridIndex g{};
        g[axis(face.normal_axis)] = face.far_side ? grid.n[axis(face.normal_axis)] : 0;
        g[axis(face.u)] = p;
        g[axis(face.v)] = q;
        const auto [it, added] = ids.try_emplace(g, mesh.node_count());
        if (added) {
            mesh.add_node(grid.spacing.cwiseProduct(Vec3(g[0], g[1], g[2])));
        }
        return it->second;
    };
    std::vector<Index> elements;
    for (int p = 0; p < grid.n[axis(face.u)]; ++p) {
        for (int q = 0; q < grid.n[axis(face.v)]; ++q) {
            elements.push_back(mesh.add_element(
                {node(p, q), node(p + 1, q), node(p + 1, q + 1), node(p, q + 1)}, thickness));
        }
    }
    return elements;
}

/// Node sets of a box from the grid indices of its nodes.
void add_box_node_sets(ShellMesh& mesh, const std::map<GridIndex, Index>& ids,
                       const std::array<int, 3>& n) {
    std::map<std::string, std::vector<Index>> sets;
    for (const auto& [g, id] : ids) {
        const bool x_end = g[0] == 0 || g[0] == n[0];
        const bool y_end = g[1] == 0 || g[1] == n[1];
        const auto add = [&, id = id](bool in, const char* name) {
            if (in) {
                sets[name].push_back(id);
            }
        };
        add(true, "all");
        add(g[2] == 0, "bottom");
        add(g[2] == 0 && (x_end || y_end), "bottom_edge");
        add(g[2] == n[2], "top");
        add(g[2] == n[2] && (x_end || y_end), "top_edge");
        add(g[0] == 0, "x0");
        add(g[0] == n[0], "x1");
        add(g[1] == 0, "y0");
        add(g[1] == n[1], "y1");
    }
    for (auto& [name, nodes] : sets) {
        std::sort(nodes.begin(), nodes.end());
        mesh.add_node_set(name, std::move(nodes));
    }
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

ShellMesh make_box(double lx, double ly, double lz, int nx, int ny, int nz, bool closed_top,
                   double thickness) {
    if (nx < 1 || ny < 1 || nz < 1) {
        throw std::invalid_argument("mesh generator: element counts must be >= 1");
    }
    const BoxGrid grid{{nx, ny, nz}, Vec3(lx / nx, ly / ny, lz / nz)};
    ShellMesh mesh;
    std::map<GridIndex, Index> ids;
    std::vector<Index> all_elements;
    for (const BoxFace& face : kBoxFaces) {
        if (!closed_top && std::string_view(face.name) == "top") {
            continue;
        }
        std::vector<Index> elements = add_box_face(mesh, ids, grid, face, thickness);
        all_elements.insert(all_elements.end(), elements.begin(), elements.end());
        mesh.add_element_set(face.name, std::move(elements));
    }
    mesh.add_element_set("all", std::move(all_elements));
    add_box_node_sets(mesh, ids, grid.n);
    return mesh;
}

} // namespace grainload::fem
