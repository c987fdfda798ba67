#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "io/surface_mesh_reader.hpp"
#include "sph/sph_case_reader.hpp"
#include "sph/surface_mesh_wall.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <limits>

namespace grainload::sph {
namespace {

std::string mesh_path(const std::string& name) {
    return std::string(GRAINLOAD_SOURCE_DIR) + "/tests/data/meshes/" + name;
}

/// Distance from p to the closed triangle abc (Ericson, Real-Time Collision Detection, 5.1.5:
/// the closest point by Voronoi regions of the vertices, edges and face).
double distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0) {
        return ap.norm();
    }
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3) {
        return bp.norm();
    }
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        return (p - (a + d1 / (d1 - d3) * ab)).norm();
    }
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6) {
        return cp.norm();
    }
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        return (p - (a + d2 / (d2 - d6) * ac)).norm();
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
        return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
    }
    const double denominator = 1.0 / (va + vb + vc);
    return (p - (a + ab * (vb * denominator) + ac * (vc * denominator))).norm();
}

double distance_to_mesh(const Vec3& p, const io::SurfaceMesh& mesh) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [a, b, c] : mesh.triangles) {
        best = std::min(
            best, distance_to_triangle(p, mesh.vertices[a], mesh.vertices[b], mesh.vertices[c]));
    }
    return best;
}

double nearest(const Vec3& p, const std::vector<Vec3>& points) {
    double best = std::numeric_limits<double>::infinity();
    for (const Vec3& q : points) {
        best = std::min(best, (p - q).norm());
    }
    return best;
}

// Layer 0 of the STL cube (side 1 m, spacing 0.07 m: not a divisor). Every particle must lie
// on a face (round-off only: the samples are affine combinations of the corners); the faces'
// right triangles (legs 1 m) get n = ceil(1 / 0.07) = 15 parts per leg, so after merging the
// shared edges and diagonals the particles are exactly the 6 n^2 + 2 = 1352 points of a
// 15 x 15 grid on each face. Coverage: every point of the surface is within spacing / sqrt(2)
// of a sample (the sub-squares have side 1/15 < 0.07), checked on a 60 x 60 grid per face.
TEST(SurfaceMeshWall, CubeLayerZeroLiesOnAndCoversTheSurface) {
    const io::SurfaceMesh cube = io::read_surface_mesh_file(mesh_path("cube_ascii.stl"));
    const double dx = 0.07;
    const auto points = mesh_wall_points(cube, dx, 1, 3, false).points;
    EXPECT_EQ(points.size(), 6u * 15u * 15u + 2u);
    double off_surface = 0.0;
    for (const Vec3& p : points) {
        off_surface = std::max(off_surface, distance_to_mesh(p, cube));
    }
    std::cout << "cube layer 0: " << points.size() << " particles, largest distance to the "
              << "surface " << off_surface << " m\n";
    EXPECT_LT(off_surface, 1e-12);
    double gap = 0.0;
    for (const auto& [a, b, c] : cube.triangles) {
        const Vec3 &xa = cube.vertices[a], &xb = cube.vertices[b], &xc = cube.vertices[c];
        const int m = 60;
        for (int i = 0; i <= m; ++i) {
            for (int j = 0; i + j <= m; ++j) {
                const Vec3 p = xa + (i / double(m)) * (xb - xa) + (j / double(m)) * (xc - xa);
                gap = std::max(gap, nearest(p, points));
            }
        }
    }
    std::cout << "cube layer 0: farthest surface point from a particle " << gap / dx
              << " spacing (bound (1/15)/sqrt(2) / 0.07 = " << (1.0 / 15) / std::sqrt(2.0) / dx
              << ")\n";
    EXPECT_LE(gap, (1.0 / 15.0) / std::sqrt(2.0) + 1e-12);
    EXPECT_LT(gap, 0.75 * dx);
}

// The cube's STL normals point outward, so with the normal "into the material" the material
// is outside and the layers go inside, k spacings deep; flip_normals puts them outside.
TEST(SurfaceMeshWall, LayersLieBehindTheFacesAtWholeSpacings) {
    const io::SurfaceMesh cube = io::read_surface_mesh_file(mesh_path("cube_ascii.stl"));
    const Vec3 lower(-0.25, -0.5, 0.0), upper(0.75, 0.5, 1.0);
    const double dx = 0.1;
    const auto depth_of = [&](const Vec3& p) { // signed: > 0 inside the cube
        return std::min((p - lower).minCoeff(), (upper - p).minCoeff());
    };
    const auto inner = mesh_wall_points(cube, dx, 3, 3, false).points;
    const auto outer = mesh_wall_points(cube, dx, 3, 3, true).points;
    std::array<int, 3> inner_count{}, outer_count{};
    for (const Vec3& p : inner) {
        const double layer = depth_of(p) / dx;
        ASSERT_NEAR(layer, std::round(layer), 1e-9);
        ASSERT_TRUE(layer > -0.5 && layer < 2.5) << layer;
        ++inner_count[static_cast<std::size_t>(std::lround(layer))];
    }
    for (const Vec3& p : outer) {
        const double layer = -depth_of(p) / dx;
        ASSERT_NEAR(layer, std::round(layer), 1e-9);
        ASSERT_TRUE(layer > -0.5 && layer < 2.5) << layer;
        EXPECT_NEAR(distance_to_mesh(p, cube), std::round(layer) * dx, 1e-12);
        ++outer_count[static_cast<std::size_t>(std::lround(layer))];
    }
    // Inside: the cube of side 1 with 10 parts per edge holds whole lattice shells; shell k is
    // the surface of a 10 - 2k grid, 6 (10 - 2k)^2 + 2 points.
    EXPECT_EQ(inner_count, (std::array<int, 3>{602, 386, 218}));
    // Outside: face layers only (no wedge around edges), shell k has the 6 * 11^2 face points
    // moved out; the 0.3 spacing merge removes nothing there.
    EXPECT_EQ(outer_count[0], 602);
    EXPECT_EQ(outer_count[1], 6 * 11 * 11);
    EXPECT_EQ(outer_count[2], 6 * 11 * 11);
}

// Gmsh quadrangles: the unit square as 2 x 2 quads, normal +z; spacing 0.1 gives 5 parts per
// quad edge, an 11 x 11 grid per layer, the second layer at z = -0.1.
TEST(SurfaceMeshWall, GmshQuadWallIsAGridPerLayer) {
    const io::SurfaceMesh square = io::read_surface_mesh_file(mesh_path("square_quads.msh"));
    const auto points = mesh_wall_points(square, 0.1, 2, 3, false).points;
    ASSERT_EQ(points.size(), 2u * 11u * 11u);
    for (std::size_t k = 0; k < points.size(); ++k) {
        EXPECT_NEAR(points[k].z(), k < 121 ? 0.0 : -0.1, 1e-15);
        const Vec3 grid = points[k] / 0.1;
        EXPECT_NEAR(grid.x(), std::round(grid.x()), 1e-12);
        EXPECT_NEAR(grid.y(), std::round(grid.y()), 1e-12);
    }
}

// Plane strain: the V polyline from (0, 1) to (1, 0) to (2, 1), material above (left of the
// walking direction). Segments of length sqrt(2) at spacing 0.1 get 15 parts: 2 x 16 points
// less the shared corner. Layer 1 lies 0.1 below each segment.
TEST(SurfaceMeshWall, PolylineWallInPlaneStrain) {
    const io::SurfaceMesh v = io::read_surface_mesh_file(mesh_path("polyline.msh"));
    const auto surface = mesh_wall_points(v, 0.1, 1, 2, false).points;
    EXPECT_EQ(surface.size(), 31u);
    for (const Vec3& p : surface) {
        EXPECT_NEAR(p.y(), std::abs(p.x() - 1.0), 1e-15);
        EXPECT_EQ(p.z(), 0.0);
    }
    const auto two = mesh_wall_points(v, 0.1, 2, 2, false).points;
    for (std::size_t k = surface.size(); k < two.size(); ++k) {
        // Below the V by one spacing, measured along the segment normal (1 / sqrt 2 per axis).
        const Vec3& p = two[k];
        EXPECT_NEAR((std::abs(p.x() - 1.0) - p.y()) / std::sqrt(2.0), 0.1, 1e-12) << p.transpose();
    }
}

/// Position of a sample from its record alone: the face's vertices weighted by face_weights,
/// moved by the offset along the face normal (right-hand rule; the left side of a segment).
Vec3 sample_position(const io::SurfaceMesh& mesh, const WallSample& sample, int dimension) {
    std::vector<Index> face;
    const auto triangles = static_cast<Index>(mesh.triangles.size());
    if (dimension == 2) {
        const auto& seg = mesh.segments[static_cast<std::size_t>(sample.face)];
        face = {seg[0], seg[1]};
    } else if (sample.face < triangles) {
        const auto& tri = mesh.triangles[static_cast<std::size_t>(sample.face)];
        face = {tri[0], tri[1], tri[2]};
    } else {
        const auto& quad = mesh.quads[static_cast<std::size_t>(sample.face - triangles)];
        face = {quad[0], quad[1], quad[2], quad[3]};
    }
    const auto weights = face_weights(sample, static_cast<int>(face.size()));
    Vec3 x = Vec3::Zero();
    for (std::size_t a = 0; a < face.size(); ++a) {
        x += weights[a] * mesh.vertices[static_cast<std::size_t>(face[a])];
    }
    const auto& v = mesh.vertices;
    Vec3 normal;
    if (face.size() == 2) {
        const Vec3 t = v[face[1]] - v[face[0]];
        normal = Vec3(-t.y(), t.x(), 0.0).normalized();
    } else if (face.size() == 3) {
        normal = (v[face[1]] - v[face[0]]).cross(v[face[2]] - v[face[0]]).normalized();
    } else { // the bilinear patch's normal x_r x x_s at (r, s)
        const double r = sample.r, s = sample.s;
        const Vec3 xr = (1 - s) * (v[face[1]] - v[face[0]]) + s * (v[face[2]] - v[face[3]]);
        const Vec3 xs = (1 - r) * (v[face[3]] - v[face[0]]) + r * (v[face[2]] - v[face[1]]);
        normal = xr.cross(xs).normalized();
    }
    return x + sample.offset * normal;
}

// Every wall particle keeps its origin (face, parametric point, side, layer offset), from which
// the face's geometry alone gives back its position: the record the coupling uses both ways.
// Checked on triangles (the STL cube, rotated barycentric grids), quadrangles (Gmsh) and
// segments (plane strain), with layers and flipped normals; round-off only.
TEST(SurfaceMeshWall, EveryParticleKnowsWhereItWasSampled) {
    struct Mesh {
        const char* file;
        int dimension;
    };
    for (const Mesh m :
         {Mesh{"cube_ascii.stl", 3}, Mesh{"square_quads.msh", 3}, Mesh{"polyline.msh", 2}}) {
        const io::SurfaceMesh mesh = io::read_surface_mesh_file(mesh_path(m.file));
        for (const bool flip : {false, true}) {
            const MeshWallSamples wall = mesh_wall_points(mesh, 0.07, 3, m.dimension, flip);
            ASSERT_EQ(wall.samples.size(), wall.points.size());
            double worst = 0.0;
            for (std::size_t k = 0; k < wall.points.size(); ++k) {
                const WallSample& sample = wall.samples[k];
                EXPECT_EQ(sample.side, flip ? -1 : 1);
                EXPECT_NEAR(sample.offset, -sample.side * sample.layer * 0.07, 1e-15);
                worst = std::max(
                    worst, (sample_position(mesh, sample, m.dimension) - wall.points[k]).norm());
            }
            EXPECT_LT(worst, 1e-12) << m.file << (flip ? " flipped" : "");
        }
    }
}

std::string wall_error(const std::string& body, int dimension) {
    auto document = io::CaseDocument::from_string("[wall]\n" + body, mesh_path("case.toml"));
    document->spatial_dimension = dimension;
    try {
        read_mesh_wall_points(document->root().table("wall"), dimension, 0.1, 2, false);
    } catch (const io::CaseError& error) {
        return error.what();
    }
    return "no CaseError";
}

TEST(SurfaceMeshWall, CaseKeysAndRefusals) {
    auto document = io::CaseDocument::from_string("[wall]\nfile = \"cube_ascii.stl\"\n",
                                                  mesh_path("case.toml"));
    EXPECT_EQ(
        read_mesh_wall_points(document->root().table("wall"), 3, 0.1, 3, true).points,
        mesh_wall_points(io::read_surface_mesh_file(mesh_path("cube_ascii.stl")), 0.1, 3, 3, true)
            .points);
    const std::string stl_in_2d = wall_error("file = \"square_quads.msh\"\n", 2);
    EXPECT_NE(stl_in_2d.find("key 'wall.file'"), std::string::npos) << stl_in_2d;
    EXPECT_NE(stl_in_2d.find("a mesh wall is a polyline"), std::string::npos) << stl_in_2d;
    const std::string lines_in_3d = wall_error("file = \"polyline.msh\"\n", 3);
    EXPECT_NE(lines_in_3d.find("needs triangles or quadrangles"), std::string::npos) << lines_in_3d;
    const std::string missing = wall_error("file = \"hopper.stl\"\n", 3);
    EXPECT_NE(missing.find("case.toml:2:"), std::string::npos) << missing;
    EXPECT_NE(missing.find("expected an existing file"), std::string::npos) << missing;
}

} // namespace
} // namespace grainload::sph
