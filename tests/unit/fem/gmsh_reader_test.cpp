#include "fem/gmsh_reader.hpp"

#include <gtest/gtest.h>
#include <sstream>

namespace grainload::fem {
namespace {

// A unit 1 x 1 square of one quad and two triangles, written as Gmsh 4.1 would: one
// surface (physical "plate"), its left edge (physical "clamped") and a corner point (no name).
constexpr const char* kSquare = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
2
1 1 "clamped"
2 2 "plate"
$EndPhysicalNames
$Entities
1 1 1 0
1 1 1 0 1 3
1 0 0 0 0 1 0 1 1 0
1 0 0 0 1 1 0 1 2 0
$EndEntities
$Nodes
1 6 1 6
2 1 0 6
1
2
3
4
5
6
0 0 0
0.5 0 0
1 0 0
0 1 0
0.5 1 0
1 1 0
$EndNodes
$Elements
4 5 1 5
0 1 15 1
1 1
1 1 1 1
2 1 4
2 1 3 1
3 1 2 5 4
2 1 2 2
4 2 3 6
5 2 6 5
$EndElements
)";

TEST(GmshReader, ReadsQuadsTrianglesAndPhysicalGroups) {
    std::istringstream in(kSquare);
    const ShellMesh mesh = read_gmsh(in, 0.01);
    EXPECT_EQ(mesh.node_count(), 6);
    ASSERT_EQ(mesh.element_count(), 3);
    EXPECT_FALSE(mesh.element(0).is_triangle());
    EXPECT_TRUE(mesh.element(1).is_triangle());
    EXPECT_EQ(mesh.node_set("clamped"), (std::vector<Index>{0, 3}));
    EXPECT_EQ(mesh.node_set("plate").size(), 6u);
    EXPECT_EQ(mesh.element_set("plate").size(), 3u);
    EXPECT_EQ(mesh.node_set("group3"), (std::vector<Index>{0}));
    EXPECT_NO_THROW(mesh.validate());
}

TEST(GmshReader, RejectsOtherVersionsAndUnknownNodes) {
    std::istringstream old("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n");
    EXPECT_THROW(read_gmsh(old, 0.01), std::invalid_argument);
    std::string bad = kSquare;
    bad.replace(bad.find("5 2 6 5"), 7, "5 2 6 9");
    std::istringstream in(bad);
    try {
        read_gmsh(in, 0.01);
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("element 5: unknown node id 9"), std::string::npos)
            << e.what();
    }
}

std::string invalid_argument_of(const std::string& text, double thickness,
                                const GroupThickness& by_group) {
    std::istringstream in(text);
    try {
        read_gmsh(in, thickness, by_group);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "no std::invalid_argument";
}

TEST(GmshReader, ThicknessByPhysicalSurface) {
    std::istringstream in(kSquare);
    const ShellMesh mesh = read_gmsh(in, 0.0, {{"plate", 0.02}});
    for (const ShellElement& element : mesh.elements()) {
        EXPECT_EQ(element.thickness, 0.02);
    }
    EXPECT_NE(invalid_argument_of(kSquare, 0.01, {{"roof", 0.02}})
                  .find("no physical surface named \"roof\" (physical surfaces: plate)"),
              std::string::npos);
    // The surface taken out of "plate": its elements have no thickness unless a default is given.
    std::string loose = kSquare;
    loose.replace(loose.find("1 0 0 0 1 1 0 1 2 0"), 19, "1 0 0 0 1 1 0 0 0");
    EXPECT_NE(invalid_argument_of(loose, 0.0, {{"plate", 0.02}})
                  .find("surface 1 is in no physical group with a thickness"),
              std::string::npos);
    std::istringstream fallback(loose);
    EXPECT_EQ(read_gmsh(fallback, 0.01, {{"plate", 0.02}}).element(0).thickness, 0.01);
}

} // namespace
} // namespace grainload::fem
