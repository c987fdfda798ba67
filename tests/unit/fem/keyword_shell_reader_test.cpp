#include "fem/keyword_shell_reader.hpp"
#include "fem/shell_case_reader.hpp"
#include "io/case_table.hpp"
#include "io/keyword_deck.hpp"
#include "support/test_folder.hpp"

#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <sstream>

namespace grainload::fem {
namespace {

namespace fs = std::filesystem;

// A floor (part 1, "floor": two quads 1 m x 0.5 m, section 1 of 5 mm) and a wall standing on
// its edge x = 0 (part 2, untitled: one quad with nodal thicknesses 4, 4, 8, 8 mm on section
// 2), in mm-t-s, plus particles of an SPH part 3 whose nodes the shell mesh must leave out.
constexpr const char* kDeck = R"(*KEYWORD
*NODE
1, 0, 0, 0
2, 500, 0, 0
3, 1000, 0, 0
4, 0, 500, 0
5, 500, 500, 0
6, 1000, 500, 0
7, 0, 0, 500
8, 0, 500, 500
100, 300, 300, 300
*SECTION_SHELL
1, 16
5.0
2, 16
3.0
*PART
floor
1, 1, 1
*PART

2, 2, 1
*ELEMENT_SHELL
1, 1, 1, 2, 5, 4
2, 1, 2, 3, 6, 5
*ELEMENT_SHELL_THICKNESS
3, 2, 4, 1, 7, 8
4.0, 4.0, 8.0, 8.0
*SET_NODE_LIST_TITLE
hinge
1
1, 4, 100
*SET_NODE_LIST
2
100
*SET_SHELL_LIST
5
2, 3
*ELEMENT_SPH
100, 3, 1e-6
*END
)";

io::KeywordMesh deck_mesh() {
    std::istringstream in(kDeck);
    std::string error;
    return io::read_keyword_mesh(io::read_keyword_deck(in, "deck.k", "."),
                                 *io::parse_keyword_units("mm-t-s", &error));
}

std::string error_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const std::exception& error) {
        return error.what();
    }
    return "no exception";
}

// Thickness from sections (mm to m: one rounding) and the mean of nodal thicknesses.
constexpr double kRoundOff = 1e-15;

TEST(KeywordShellReader, AllShellPartsWithThicknessAndSets) {
    const ShellMesh mesh = make_keyword_shell_mesh(deck_mesh(), {});
    EXPECT_EQ(mesh.node_count(), 8); // node 100 (a particle) is no shell node
    ASSERT_EQ(mesh.element_count(), 3);
    EXPECT_NEAR((mesh.node(7) - Vec3(0.0, 0.5, 0.5)).norm(), 0.0, kRoundOff);
    EXPECT_NEAR(mesh.element(0).thickness, 0.005, kRoundOff);
    EXPECT_NEAR(mesh.element(2).thickness, 0.006, kRoundOff); // (4 + 4 + 8 + 8) / 4 mm
    EXPECT_EQ(mesh.element(2).nodes, (std::array<Index, 4>{3, 0, 6, 7}));
    EXPECT_EQ(mesh.element_set("floor"), (std::vector<Index>{0, 1}));
    EXPECT_EQ(mesh.element_set("part2"), (std::vector<Index>{2}));
    EXPECT_EQ(mesh.node_set("part2"), (std::vector<Index>{0, 3, 6, 7}));
    EXPECT_EQ(mesh.node_set("hinge"), (std::vector<Index>{0, 3}));
    EXPECT_FALSE(mesh.has_node_set("set2")); // only node 100, not in the mesh
    EXPECT_EQ(mesh.element_set("set5"), (std::vector<Index>{1, 2}));
    mesh.validate();
}

TEST(KeywordShellReader, SelectsPartsByTitleOrId) {
    const ShellMesh floor = make_keyword_shell_mesh(deck_mesh(), {"floor"});
    EXPECT_EQ(floor.element_count(), 2);
    EXPECT_EQ(floor.node_count(), 6);
    EXPECT_EQ(floor.element_set("set5"), (std::vector<Index>{1}));
    const ShellMesh wall = make_keyword_shell_mesh(deck_mesh(), {"2"});
    EXPECT_EQ(wall.element_count(), 1);
    const std::string unknown = error_of([] { make_keyword_shell_mesh(deck_mesh(), {"roof"}); });
    EXPECT_NE(unknown.find("no *PART titled \"roof\" (parts with shell elements: 1 \"floor\", 2)"),
              std::string::npos)
        << unknown;
    const std::string particles = error_of([] { make_keyword_shell_mesh(deck_mesh(), {"3"}); });
    EXPECT_NE(particles.find("part 3 (\"3\") has no shell elements"), std::string::npos)
        << particles;
}

TEST(KeywordShellReader, RefusesPartsWithoutShellSection) {
    std::string deck = kDeck;
    deck.replace(deck.find("2, 2, 1\n"), 8, "2, 9, 1\n");
    std::istringstream in(deck);
    std::string error;
    const io::KeywordMesh mesh = io::read_keyword_mesh(io::read_keyword_deck(in, "deck.k", "."),
                                                       *io::parse_keyword_units("m-kg-s", &error));
    const std::string missing = error_of([&] { make_keyword_shell_mesh(mesh, {}); });
    EXPECT_NE(missing.find("deck.k:22: *PART 2: SECID 9 is not a *SECTION_SHELL"),
              std::string::npos)
        << missing;
}

// The case-file route: generator = "lsdyna" with units and parts, a warning-free deck, and the
// node sets usable by boundaries.
TEST(KeywordShellReader, CaseFileGeneratorLsdyna) {
    const std::string dir = grainload::testing::process_folder() + "keyword_shell_case";
    fs::create_directories(dir);
    std::ofstream(dir + "/deck.k") << kDeck;
    const std::string text = R"([[shell]]
generator = "lsdyna"
file = "deck.k"
units = "mm-t-s"
parts = ["floor", 2]
)";
    auto document = io::CaseDocument::from_string(text, dir + "/case.toml");
    const ShellMesh mesh = read_shell_mesh(document->root().array_of_tables("shell").front());
    EXPECT_EQ(mesh.element_count(), 3);
    EXPECT_NEAR(mesh.element(1).thickness, 0.005, kRoundOff);
    auto bad = io::CaseDocument::from_string(
        "[[shell]]\ngenerator = \"lsdyna\"\nfile = \"deck.k\"\nunits = \"mm-s-t\"\n",
        dir + "/case.toml");
    const std::string units =
        error_of([&] { read_shell_mesh(bad->root().array_of_tables("shell").front()); });
    EXPECT_NE(units.find("shell[0].units"), std::string::npos) << units;
}

} // namespace
} // namespace grainload::fem
