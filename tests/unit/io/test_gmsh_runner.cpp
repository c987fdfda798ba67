#include "io/gmsh_file.hpp"
#include "io/gmsh_runner.hpp"
#include "support/test_folder.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

namespace {

using namespace grainload::io;
namespace fs = std::filesystem;

// A 1 m x 0.5 m rectangle meshed with quadrangles of 0.25 m: 4 x 2 of them.
constexpr const char* kRectangle = R"(Point(1) = {0, 0, 0, 0.25};
Point(2) = {1, 0, 0, 0.25};
Point(3) = {1, 0.5, 0, 0.25};
Point(4) = {0, 0.5, 0, 0.25};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("plate") = {1};
Physical Curve("clamped") = {4};
)";

std::string fresh_directory(const std::string& name) {
    const std::string dir = grainload::testing::process_folder() + "gmsh_runner_" + name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TEST(GmshRunner, MeshesWhenMissingOrOlderThanTheGeometry) {
    const std::string dir = fresh_directory("remesh");
    const std::string geo = dir + "/plate.geo";
    const std::string msh = dir + "/plate.msh";
    std::ofstream(geo) << kRectangle;
    EXPECT_TRUE(gmsh_mesh_outdated(geo, msh));
    EXPECT_TRUE(ensure_gmsh_mesh(geo, msh));
    std::ifstream in(msh);
    const GmshFile file = read_gmsh_file_content(in, msh);
    std::size_t quads = 0;
    for (const GmshElement& element : file.elements) {
        quads += element.node_count == 4 ? 1 : 0;
    }
    EXPECT_EQ(quads, 8u); // transfinite 4 x 2
    EXPECT_EQ(file.nodes.size(), 15u);
    EXPECT_EQ(file.physical_names.at({2, 1}), "plate");
    EXPECT_FALSE(ensure_gmsh_mesh(geo, msh)); // up to date
    fs::last_write_time(geo, fs::last_write_time(msh) + std::chrono::seconds(10));
    EXPECT_TRUE(ensure_gmsh_mesh(geo, msh));
    // Only the two files remain: the temporary mesh and Gmsh's log are gone.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
}

// The rectangle with its size a DefineConstant: -setnumber h 0.125 (geo_numbers) halves the
// quadrangles' size, 8 x 4 of them, against 4 x 2 at the script's own 0.25.
TEST(GmshRunner, NumbersOverrideTheScriptsConstants) {
    const std::string dir = fresh_directory("numbers");
    const std::string geo = dir + "/plate.geo";
    std::string text = kRectangle;
    for (std::size_t at = text.find("0.25}"); at != std::string::npos; at = text.find("0.25}")) {
        text.replace(at, 4, "h");
    }
    std::ofstream(geo) << "DefineConstant[ h = {0.25, Name \"size\"} ];\n" << text;
    auto quads = [](const std::string& msh) {
        std::ifstream in(msh);
        const GmshFile file = read_gmsh_file_content(in, msh);
        return std::count_if(file.elements.begin(), file.elements.end(),
                             [](const GmshElement& e) { return e.node_count == 4; });
    };
    ASSERT_TRUE(ensure_gmsh_mesh(geo, dir + "/own.msh"));
    ASSERT_TRUE(ensure_gmsh_mesh(geo, dir + "/fine.msh", {{"h", 0.125}}));
    EXPECT_EQ(quads(dir + "/own.msh"), 8);
    EXPECT_EQ(quads(dir + "/fine.msh"), 32);
    // The numbers a mesh was made with are part of being up to date: the same numbers keep
    // it, other numbers (a case that changed its mesh size) remake it.
    EXPECT_FALSE(ensure_gmsh_mesh(geo, dir + "/own.msh"));
    EXPECT_FALSE(ensure_gmsh_mesh(geo, dir + "/fine.msh", {{"h", 0.125}}));
    EXPECT_TRUE(ensure_gmsh_mesh(geo, dir + "/fine.msh", {{"h", 0.25}}));
    EXPECT_EQ(quads(dir + "/fine.msh"), 8);
    EXPECT_TRUE(ensure_gmsh_mesh(geo, dir + "/fine.msh"));
}

TEST(GmshRunner, GmshErrorsAreQuoted) {
    const std::string dir = fresh_directory("error");
    const std::string geo = dir + "/broken.geo";
    std::ofstream(geo) << "Point(1) = {0, 0, 0, 0.1};\nLine(1) = {1, 7};\n";
    try {
        ensure_gmsh_mesh(geo, dir + "/broken.msh");
        FAIL() << "a line to an unknown point was meshed";
    } catch (const std::invalid_argument& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("gmsh failed to mesh " + geo), std::string::npos) << message;
        EXPECT_NE(message.find("Error"), std::string::npos) << message;
    }
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

} // namespace
