#include "io/case_table.hpp"
#include "io/surface_mesh_reader.hpp"
#include "support/test_folder.hpp"

#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <stdexcept>

namespace {

using namespace grainload;
using namespace grainload::io;

std::string mesh_path(const std::string& name) {
    return std::string(GRAINLOAD_SOURCE_DIR) + "/tests/data/meshes/" + name;
}

/// A case document "located" in tests/data/meshes, so that `file` keys resolve there.
std::unique_ptr<CaseDocument> mesh_case(const std::string& text, int dimension = 3) {
    auto document = CaseDocument::from_string(text, mesh_path("case.toml"));
    document->spatial_dimension = dimension;
    return document;
}

std::string case_error_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const CaseError& error) {
        return error.what();
    }
    return "no CaseError";
}

std::string invalid_argument_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return "no std::invalid_argument";
}

std::string write_temp(const std::string& name, const std::string& text) {
    const std::string path = grainload::testing::process_folder() + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

// The two fixtures hold the same cube, written by tests/data/meshes/make_meshes.py with
// coordinates exact in float32; the readers must agree bit for bit. STL repeats each corner
// in every triangle: welding leaves the cube's 8 corners and its 12 triangles.
TEST(SurfaceMeshReader, AsciiAndBinaryStlOfOneCubeAreIdentical) {
    const SurfaceMesh ascii = read_surface_mesh_file(mesh_path("cube_ascii.stl"));
    const SurfaceMesh binary = read_surface_mesh_file(mesh_path("cube_binary.stl"));
    ASSERT_EQ(ascii.vertices.size(), 8u);
    ASSERT_EQ(ascii.triangles.size(), 12u);
    EXPECT_EQ(ascii.vertices, binary.vertices);
    EXPECT_EQ(ascii.triangles, binary.triangles);
    EXPECT_TRUE(ascii.quads.empty() && ascii.segments.empty());
    // First facet of the file: (-0.25, -0.5, 0), (-0.25, 0.5, 0), (0.75, 0.5, 0).
    const auto& first = ascii.triangles.front();
    EXPECT_EQ(ascii.vertices[first[0]], Vec3(-0.25, -0.5, 0.0));
    EXPECT_EQ(ascii.vertices[first[2]], Vec3(0.75, 0.5, 0.0));
}

TEST(SurfaceMeshReader, GmshQuadsLinesAndSkippedPoints) {
    const SurfaceMesh square = read_surface_mesh_file(mesh_path("square_quads.msh"));
    EXPECT_EQ(square.vertices.size(), 9u);
    ASSERT_EQ(square.quads.size(), 4u);
    EXPECT_EQ(square.quads[3], (std::array<Index, 4>{4, 5, 8, 7}));
    EXPECT_TRUE(square.triangles.empty() && square.segments.empty());
    const SurfaceMesh polyline = read_surface_mesh_file(mesh_path("polyline.msh"));
    ASSERT_EQ(polyline.segments.size(), 2u);
    EXPECT_EQ(polyline.segments[1], (std::array<Index, 2>{1, 2}));
    EXPECT_EQ(polyline.vertices[2], Vec3(2.0, 1.0, 0.0));
}

// What Gmsh writes with physical groups: $PhysicalNames and $Entities are skipped, a
// parametric node block keeps x y z, and one file mixes points, lines, triangles and quads.
TEST(SurfaceMeshReader, GmshSkipsGroupsAndMixesElementTypes) {
    const std::string path = write_temp("groups.msh", R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
1
2 7 "hopper wall"
$EndPhysicalNames
$Entities
0 0 1 0
3 0 0 0 2 1 0 1 7 0
$EndEntities
$Nodes
2 5 1 5
2 3 0 4
1
2
3
4
0 0 0
2 0 0
2 1 0
0 1 0
2 3 1 1
5
1 0.5 0 0.25 0.5
$EndNodes
$Elements
3 4 1 4
0 1 15 1
1 5
1 3 1 1
2 1 2
2 3 2 2
3 1 2 5
4 2 3 5
$EndElements
)");
    const SurfaceMesh mesh = read_surface_mesh_file(path);
    ASSERT_EQ(mesh.vertices.size(), 5u);
    EXPECT_EQ(mesh.vertices[4], Vec3(1.0, 0.5, 0.0));
    EXPECT_EQ(mesh.segments.size(), 1u);
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.triangles[1], (std::array<Index, 3>{1, 2, 4}));
    EXPECT_TRUE(mesh.quads.empty());
}

TEST(SurfaceMeshReader, UnitScaleAndOffsetFromTheCaseTable) {
    const auto document = mesh_case(R"(
[wall]
file = "cube_ascii.stl"
unit = "mm"
scale = 2.0
offset = "1 2 3 m"
)");
    const SurfaceMesh mesh = read_surface_mesh(document->root().table("wall"));
    // (0.75, 0.5, 0) mm * 2 + (1, 2, 3) m.
    const Vec3 expected = 2e-3 * Vec3(0.75, 0.5, 0.0) + Vec3(1.0, 2.0, 3.0);
    EXPECT_LT((mesh.vertices[mesh.triangles[0][2]] - expected).norm(), 1e-15);
}

TEST(SurfaceMeshReader, BadMeshesNameTheKey) {
    const auto error_for = [](const std::string& body, int dimension = 3) {
        const auto document = mesh_case("[wall]\n" + body, dimension);
        return case_error_of([&] { read_surface_mesh(document->root().table("wall")); });
    };
    const std::string missing = error_for("file = \"no_such.stl\"\n");
    EXPECT_NE(missing.find("case.toml:2:"), std::string::npos) << missing;
    EXPECT_NE(missing.find("key 'wall.file'"), std::string::npos) << missing;
    EXPECT_NE(missing.find("expected an existing file"), std::string::npos) << missing;
    const std::string degenerate = error_for("file = \"degenerate.stl\"\n");
    EXPECT_NE(degenerate.find("key 'wall.file'"), std::string::npos) << degenerate;
    EXPECT_NE(degenerate.find("triangle 4 of the mesh is degenerate"), std::string::npos)
        << degenerate;
    const std::string unit = error_for("file = \"cube_ascii.stl\"\nunit = \"kg\"\n");
    EXPECT_NE(unit.find("key 'wall.unit'"), std::string::npos) << unit;
    const std::string plane = error_for("file = \"cube_ascii.stl\"\n", 2);
    EXPECT_NE(plane.find("must lie in z = 0"), std::string::npos) << plane;
}

TEST(SurfaceMeshReader, MalformedFilesNameFileAndLine) {
    const std::string ascii =
        write_temp("bad.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                              "vertex 1 0\n");
    EXPECT_NE(invalid_argument_of([&] { read_surface_mesh_file(ascii); }).find("bad.stl:5:"),
              std::string::npos);
    const std::string quad_facet = write_temp(
        "quad.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                    "vertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid x\n");
    EXPECT_NE(invalid_argument_of([&] {
                  read_surface_mesh_file(quad_facet);
              }).find("quad.stl:8: a facet has 4 vertices"),
              std::string::npos);
    const std::string garbage = write_temp("garbage.stl", "hello");
    EXPECT_NE(invalid_argument_of([&] { read_surface_mesh_file(garbage); }).find("not an STL"),
              std::string::npos);
    const std::string binary_msh =
        write_temp("binary.msh", "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n");
    EXPECT_NE(invalid_argument_of([&] {
                  read_surface_mesh_file(binary_msh);
              }).find("binary.msh:2: MSH format 4.1 binary is not supported"),
              std::string::npos);
    const std::string tetra =
        write_temp("tetra.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1 1 1\n"
                                "3 1 0 1\n1\n0 0 0\n$EndNodes\n$Elements\n1 1 1 1\n3 1 4 1\n"
                                "1 1 1 1 1\n$EndElements\n");
    EXPECT_NE(invalid_argument_of([&] {
                  read_surface_mesh_file(tetra);
              }).find("tetra.msh:12: element type 4 is not supported"),
              std::string::npos);
    const std::string obj = write_temp("shape.obj", "v 0 0 0\n");
    EXPECT_NE(invalid_argument_of([&] {
                  read_surface_mesh_file(obj);
              }).find("unknown mesh format \".obj\""),
              std::string::npos);
}

} // namespace
