#include "io/deck_ledger.hpp"
#include "io/keyword_deck.hpp"
#include "io/keyword_fields.hpp"
#include "io/keyword_mesh.hpp"
#include "io/keyword_units.hpp"
#include "support/test_folder.hpp"

#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>

namespace {

using namespace grainload;
using namespace grainload::io;
namespace fs = std::filesystem;

// Decks written by hand as an LS-DYNA user would, in millimetres, tonnes and seconds: two
// unit squares of 1000 mm, one quadrangle and one triangle (N4 = N3), 5 mm thick.

// Fixed format: *NODE in I8 3E16, *ELEMENT_SHELL in 10 I8, the other cards in 10-column fields.
constexpr const char* kFixedDeck = R"(*KEYWORD
*TITLE
two plates, fixed format
$ a comment line
*NODE
$#   nid               x               y               z      tc      rc
       1             0.0             0.0             0.0
       2          1000.0             0.0             0.0
       3          1000.0          1000.0             0.0
       4             0.0          1000.0             0.0
       5          2000.0             0.0             0.0
       6          2000.0          1000.0          2.5E+2
*SECTION_SHELL_TITLE
thin sheet
$#   secid    elform      shrf       nip     propt   qr/irid     icomp     setyp
         1        16       1.0         5
$#      t1        t2        t3        t4      nloc     marea      idof    edgset
       5.0
*PART
plate one
         1         1         1
*ELEMENT_SHELL
       1       1       1       2       3       4
       2       1       2       5       6       6

*END
text after *END is not read
)";

// The same deck in free format: comma-separated fields, blanks trimmed, empty fields blank.
constexpr const char* kFreeDeck = R"(*KEYWORD
*NODE
1, 0.0, 0.0, 0.0
2, 1000., 0, 0
3, 1000.0, 1000.0, 0.0
4,0,1000,0
5, 2.0d3, 0.0, 0.0
6, 2000.0, 1000.0, 250
*SECTION_SHELL_TITLE
thin sheet
1, 16, 1.0, 5
5.0,,,
*PART
plate one
1, 1, 1
*ELEMENT_SHELL
1, 1, 1, 2, 3, 4
2, 1, 2, 5, 6
*END
)";

/// A fresh directory for one test's files.
std::string fresh_directory(const std::string& name) {
    const std::string dir = grainload::testing::process_folder() + "keyword_deck_" + name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string write(const std::string& path, const std::string& text) {
    fs::create_directories(fs::path(path).parent_path());
    std::ofstream(path) << text;
    return path;
}

KeywordUnits units(const std::string& name) {
    std::string error;
    const auto system = parse_keyword_units(name, &error);
    EXPECT_TRUE(system) << error;
    return system.value_or(KeywordUnits{});
}

KeywordMesh read_mesh(const std::string& path, const std::string& system = "mm-t-s") {
    return read_keyword_mesh(read_keyword_deck(path), units(system));
}

std::string error_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const KeywordError& error) {
        return error.what();
    }
    return "no KeywordError";
}

// Lengths in mm become metres by one multiplication with 1e-3: one rounding, below 1e-15 m on
// values of a few metres.
constexpr double kRoundOff = 1e-15;

void expect_two_plates(const KeywordMesh& mesh) {
    ASSERT_EQ(mesh.nodes.size(), 6u);
    EXPECT_NEAR((mesh.nodes[5] - Vec3(2.0, 1.0, 0.25)).norm(), 0.0, kRoundOff);
    EXPECT_EQ(mesh.node_ids[5], 6);
    ASSERT_EQ(mesh.shells.size(), 2u);
    EXPECT_EQ(mesh.shells[0].nodes, (std::array<KeywordId, 4>{1, 2, 3, 4}));
    EXPECT_EQ(mesh.shells[1].nodes, (std::array<KeywordId, 4>{2, 5, 6, 6})); // triangle
    EXPECT_EQ(mesh.shells[1].part, 1);
    ASSERT_EQ(mesh.sections.count(1), 1u);
    const KeywordShellSection& section = mesh.sections.at(1);
    EXPECT_EQ(section.title, "thin sheet");
    EXPECT_EQ(section.element_form, 16);
    for (const double t : section.thickness) { // T2..T4 blank: T1
        EXPECT_NEAR(t, 0.005, kRoundOff);
    }
    ASSERT_EQ(mesh.parts.count(1), 1u);
    EXPECT_EQ(mesh.parts.at(1).title, "plate one");
    EXPECT_EQ(mesh.parts.at(1).section, 1);
    EXPECT_TRUE(mesh.ignored.empty());
}

TEST(KeywordDeck, FixedFormatCards) {
    const std::string dir = fresh_directory("fixed");
    const KeywordDeck deck = read_keyword_deck(write(dir + "/plates.k", kFixedDeck));
    EXPECT_EQ(deck.title, "two plates, fixed format");
    // The blank line before *END ends the keyword; it is not a card of all defaults.
    ASSERT_EQ(deck.find("ELEMENT_SHELL").size(), 1u);
    EXPECT_EQ(deck.find("ELEMENT_SHELL").front()->cards.size(), 2u);
    expect_two_plates(read_keyword_mesh(deck, units("mm-t-s")));
}

TEST(KeywordDeck, FreeFormatCardsGiveTheSameMesh) {
    const std::string dir = fresh_directory("free");
    expect_two_plates(read_mesh(write(dir + "/plates.k", kFreeDeck)));
}

TEST(KeywordDeck, LongAndI10Formats) {
    const std::string dir = fresh_directory("long");
    // '+' after a keyword: every field 20 wide; '%': fields narrower than 10 become 10; a
    // *KEYWORD LONG=Y deck is long throughout unless a keyword says '-'.
    const std::string suffixes =
        "*KEYWORD\n*NODE +\n"
        "                   1                 0.0                 0.0"
        "                 0.0\n"
        "*ELEMENT_SHELL %\n"
        "         1         1         1         1         1         1\n"
        "*NODE -\n       2             1.0             0.0             0.0\n";
    const KeywordMesh mesh = read_mesh(write(dir + "/suffix.k", suffixes), "m-kg-s");
    EXPECT_EQ(mesh.node_ids, (std::vector<KeywordId>{1, 2}));
    EXPECT_EQ(mesh.nodes[1], Vec3(1.0, 0.0, 0.0));
    ASSERT_EQ(mesh.shells.size(), 1u);
    EXPECT_EQ(mesh.shells[0].part, 1);
    const std::string long_deck = "*KEYWORD LONG=Y\n*NODE\n"
                                  "                   7                 0.5                 0.0"
                                  "                 0.0\n";
    const KeywordDeck deck = read_keyword_deck(write(dir + "/long.k", long_deck));
    EXPECT_EQ(deck.keywords.front().format, CardFormat::long_format);
    EXPECT_EQ(read_keyword_mesh(deck, units("m-kg-s")).nodes.front(), Vec3(0.5, 0.0, 0.0));
}

TEST(KeywordDeck, IncludesRelativeToTheIncludingFile) {
    const std::string dir = fresh_directory("include");
    // main.k includes parts/plates.k, which includes ../nodes.k relative to its own folder;
    // the included keywords stand where the *INCLUDE stood.
    const std::string text = kFixedDeck;
    const auto node_start = text.find("*NODE");
    const auto node_end = text.find("*SECTION_SHELL_TITLE");
    write(dir + "/nodes.k", "*KEYWORD\n" + text.substr(node_start, node_end - node_start));
    write(dir + "/parts/plates.k",
          "*INCLUDE\n../nodes.k\n" + text.substr(node_end, text.find("*END") - node_end));
    const std::string main =
        write(dir + "/main.k", "*KEYWORD\n*INCLUDE\nparts/plat +\nes.k\n*END\n");
    const KeywordDeck deck = read_keyword_deck(main);
    EXPECT_EQ(deck.keywords.front().name, "NODE");
    EXPECT_EQ(deck.keywords.front().file, dir + "/parts/../nodes.k");
    expect_two_plates(read_keyword_mesh(deck, units("mm-t-s")));
}

TEST(KeywordDeck, RefusesIncludeCyclesAndMissingFiles) {
    const std::string dir = fresh_directory("cycle");
    write(dir + "/a.k", "*KEYWORD\n*INCLUDE\nb.k\n");
    write(dir + "/b.k", "*NODE\n1,0,0,0\n*INCLUDE\n\nsub/../a.k\n");
    const std::string cycle = error_of([&] { read_keyword_deck(dir + "/a.k"); });
    EXPECT_NE(cycle.find(dir + "/b.k:5: *INCLUDE \"sub/../a.k\" would include itself"),
              std::string::npos)
        << cycle;
    write(dir + "/c.k", "*INCLUDE\nmissing.k\n");
    const std::string missing = error_of([&] { read_keyword_deck(dir + "/c.k"); });
    EXPECT_NE(missing.find(dir + "/c.k:2: *INCLUDE: cannot open"), std::string::npos) << missing;
    write(dir + "/d.k", "*INCLUDE_TRANSFORM\nx.k\n");
    EXPECT_NE(error_of([&] { read_keyword_deck(dir + "/d.k"); }).find("d.k:1:"), std::string::npos);
}

/// The message of reading a deck whose *NODE card (line 3) is `card`.
std::string node_card_error(const std::string& dir, const std::string& card) {
    const std::string path = write(dir + "/bad.k", "*KEYWORD\n*NODE\n" + card + "\n");
    return error_of([&] { read_mesh(path); });
}

TEST(KeywordDeck, MalformedCardsNameFileLineCardAndField) {
    const std::string dir = fresh_directory("malformed");
    const std::string bad_x = node_card_error(dir, "       1             abc             0.0");
    EXPECT_NE(bad_x.find(dir + "/bad.k:3: *NODE card \"1             abc             0.0\": "
                               "field X (columns 9-24): expected a real number, got \"abc\""),
              std::string::npos)
        << bad_x;
    const std::string free = node_card_error(dir, "1, 0.0, 1.5-3");
    EXPECT_NE(free.find("field Y (free-format field 3): expected a real number, got \"1.5-3\" "
                        "(write the exponent with E"),
              std::string::npos)
        << free;
    EXPECT_NE(node_card_error(dir, "     1.5")
                  .find("field NID (columns 1-8): expected an "
                        "integer, got \"1.5\""),
              std::string::npos);
    EXPECT_NE(node_card_error(dir, "&nid, 0, 0, 0").find("*PARAMETER references"),
              std::string::npos);
    EXPECT_NE(node_card_error(dir, "1\t0.0").find("bad.k:3: *NODE card"), std::string::npos);
    EXPECT_NE(node_card_error(dir, "1,0,0,0\n1,1,0,0").find("bad.k:4:"), std::string::npos);
    const std::string outside =
        error_of([&] { read_keyword_deck(write(dir + "/outside.k", "$ fine\n\n1, 0, 0, 0\n")); });
    EXPECT_NE(outside.find("outside.k:3: card \"1, 0, 0, 0\" outside any keyword"),
              std::string::npos)
        << outside;
    const std::string eight = error_of(
        [&] { read_mesh(write(dir + "/eight.k", "*ELEMENT_SHELL\n1,1,1,2,3,4,5,6,7,8\n")); });
    EXPECT_NE(eight.find("eight.k:2: *ELEMENT_SHELL card \"1,1,1,2,3,4,5,6,7,8\": field N5"),
              std::string::npos)
        << eight;
    const std::string unknown_node = error_of([&] {
        read_mesh(write(dir + "/node.k", "*NODE\n1,0,0,0\n*ELEMENT_SHELL\n1,1,1,1,2,2\n"));
    });
    EXPECT_NE(unknown_node.find("node.k:4: *ELEMENT_SHELL 1: node 2 is not defined"),
              std::string::npos)
        << unknown_node;
    const std::string short_section =
        error_of([&] { read_mesh(write(dir + "/section.k", "*SECTION_SHELL\n1, 16\n*END\n")); });
    EXPECT_NE(short_section.find("section.k:1: *SECTION_SHELL: expected two cards"),
              std::string::npos)
        << short_section;
}

TEST(KeywordDeck, UnsupportedKeywordsInOneWarningAndRefusedVariants) {
    const std::string dir = fresh_directory("unsupported");
    const std::string deck = std::string(kFreeDeck).substr(0, std::string(kFreeDeck).find("*END")) +
                             "*MAT_ELASTIC\n1, 7.85e-9, 210000., 0.3\n*MAT_ELASTIC\n"
                             "2, 7.85e-9, 210000., 0.3\n*CONTROL_TERMINATION\n1.0\n"
                             "*BOUNDARY_SPC_SET\n1, 0, 1, 1, 1\n*NODE\n7, 0, 0, 0, 7, 0\n";
    const KeywordMesh mesh = read_mesh(write(dir + "/deck.k", deck));
    // Each where it stands: kFreeDeck's 18 lines before its *END, then these.
    std::vector<std::string> ignored;
    for (const IgnoredKeyword& k : mesh.ignored) {
        ignored.push_back(k.name + " at " + std::to_string(k.line));
    }
    EXPECT_EQ(ignored, (std::vector<std::string>{
                           "*MAT_ELASTIC at 19", "*MAT_ELASTIC at 21", "*CONTROL_TERMINATION at 23",
                           "*BOUNDARY_SPC_SET at 25", "*NODE TC/RC constraints at 28"}));
    DeckLedger ledger;
    ledger.leave(dir + "/deck.k", mesh.ignored);
    EXPECT_EQ(ledger.warnings(),
              (std::vector<std::string>{
                  dir + "/deck.k: ignored what grainload does not read from LS-DYNA decks: "
                        "*BOUNDARY_SPC_SET, *CONTROL_TERMINATION, *MAT_ELASTIC (2), *NODE TC/RC "
                        "constraints"}));
    const std::string offset = error_of(
        [&] { read_mesh(write(dir + "/offset.k", "*ELEMENT_SHELL_OFFSET\n1,1,1,2,3,4\n")); });
    EXPECT_NE(offset.find("offset.k:1: *ELEMENT_SHELL_OFFSET: this variant is not supported"),
              std::string::npos)
        << offset;
}

// One deck read by several readers (a material, bodies, shell parts): one unit system, one
// warning, and a keyword one reader took is not ignored. The same file under two spellings of
// its path is one deck; what two readers leave at the same line counts once.
TEST(KeywordDeck, TheLedgerReportsEachDeckOnceWithWhatNoReaderTook) {
    const std::string dir = fresh_directory("ledger");
    const std::string deck = std::string(kFreeDeck).substr(0, std::string(kFreeDeck).find("*END")) +
                             "*MAT_ELASTIC\n1, 7.85e-9, 210000., 0.3\n*MAT_ELASTIC\n"
                             "2, 7.85e-9, 210000., 0.3\n";
    const std::string path = write(dir + "/deck.k", deck);
    const KeywordMesh mesh = read_mesh(path);
    DeckLedger ledger;
    EXPECT_FALSE(ledger.open(path, units("mm-t-s"), "fem.shell[0].units"));
    ledger.leave(path, mesh.ignored);
    // The same units named by force: mm-N-s is mm-t-s.
    EXPECT_FALSE(ledger.open(dir + "/./deck.k", units("mm-N-s"), "fem.shell[1].units"));
    ledger.leave(dir + "/./deck.k", mesh.ignored);
    ledger.take(path, path, 19); // a material reader took the first *MAT_ELASTIC
    EXPECT_EQ(ledger.warnings(),
              (std::vector<std::string>{
                  path + ": ignored what grainload does not read from LS-DYNA decks: "
                         "*MAT_ELASTIC"}));
    const auto other = ledger.open(path, units("m-kg-s"), "sph.body[0].shape.units");
    ASSERT_TRUE(other);
    EXPECT_EQ(other->key, "fem.shell[0].units");
    EXPECT_EQ(other->units, "mm-t-s");
    ledger.take(path, path, 21);
    EXPECT_TRUE(ledger.warnings().empty());
}

TEST(KeywordDeck, ThicknessSetsAndParticles) {
    const std::string dir = fresh_directory("sets");
    const std::string deck = std::string(kFreeDeck).substr(0, std::string(kFreeDeck).find("*END")) +
                             "*ELEMENT_SHELL_THICKNESS\n3, 1, 1, 2, 3, 4\n4.0, 0.0, 6.0, 6.0\n"
                             "*SET_NODE_LIST_TITLE\nclamped edge\n7\n1, 4\n"
                             "*SET_SHELL_LIST\n8\n1, 3,\n"
                             "*ELEMENT_SPH\n"
                             "      11       3          2.5E-6      13\n"
                             "*ELEMENT_SPH_VOLUME\n20, 4, 8.0\n*ELEMENT_SPH\n21, 4, -8.0\n";
    const KeywordMesh mesh = read_mesh(write(dir + "/deck.k", deck));
    ASSERT_EQ(mesh.shells.size(), 3u);
    ASSERT_TRUE(mesh.shells[2].thickness);
    EXPECT_NEAR((*mesh.shells[2].thickness)[0], 0.004, kRoundOff);
    EXPECT_EQ((*mesh.shells[2].thickness)[1], 0.0); // 0: the section's
    ASSERT_EQ(mesh.node_sets.size(), 1u);
    EXPECT_EQ(mesh.node_sets[0].title, "clamped edge");
    EXPECT_EQ(mesh.node_sets[0].id, 7);
    EXPECT_EQ(mesh.node_sets[0].members, (std::vector<KeywordId>{1, 4}));
    ASSERT_EQ(mesh.shell_sets.size(), 1u);
    EXPECT_EQ(mesh.shell_sets[0].members, (std::vector<KeywordId>{1, 3}));
    // NID 11 .. NEND 13: three particles of 2.5e-6 t = 2.5e-3 kg; volumes in mm^3 -> m^3.
    ASSERT_EQ(mesh.particles.size(), 5u);
    EXPECT_EQ(mesh.particles[2].node, 13);
    EXPECT_NEAR(mesh.particles[2].mass, 2.5e-3, 1e-18);
    EXPECT_FALSE(mesh.particles[2].is_volume);
    for (std::size_t k = 3; k < 5; ++k) {
        EXPECT_TRUE(mesh.particles[k].is_volume);
        EXPECT_NEAR(mesh.particles[k].mass, 8e-9, 1e-22);
    }
}

// Found by tests/fuzz/fuzz_keyword: NID..NEND asked for up to 3.3e7 particles per card, a
// vector of gigabytes, with two nodes in the deck. Each particle needs a node, so a range
// longer than the *NODE cards is refused with the card named.
TEST(KeywordDeck, AParticleRangeLongerThanTheNodesIsRefused) {
    const std::string dir = fresh_directory("sph_range");
    const std::string deck = "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n*ELEMENT_SPH\n"
                             "1, 3, 1.0E-6, 33333333\n*END\n";
    const std::string error = error_of([&] { read_mesh(write(dir + "/range.k", deck)); });
    EXPECT_NE(error.find("range.k:5: *ELEMENT_SPH card"), std::string::npos) << error;
    EXPECT_NE(error.find("particles NID..NEND = 1..33333333 are more than the deck's 2 *NODE "
                         "cards"),
              std::string::npos)
        << error;
    const std::string fits = "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n*ELEMENT_SPH\n1, 3, 1.0E-6, 2\n";
    EXPECT_EQ(read_mesh(write(dir + "/fits.k", fits)).particles.size(), 2u);
}

// Consistent systems: the SI value of each deck unit against its textbook value.
TEST(KeywordUnits, ConsistentSystemsConvertToSi) {
    constexpr double kRelative = 1e-12; // double round-off of a few products
    const auto expect_relative = [](double value, double reference) {
        EXPECT_NEAR(value, reference, kRelative * std::abs(reference));
    };
    const KeywordUnits mm_t_s = units("mm-t-s"); // N, MPa, t/mm^3
    expect_relative(mm_t_s.to_si(dimension::kForce), 1.0);
    expect_relative(mm_t_s.to_si(dimension::kPressure), 1e6);
    expect_relative(mm_t_s.to_si(dimension::kDensity), 1e12);
    const KeywordUnits mm_kg_ms = units("mm-kg-ms"); // kN, GPa
    expect_relative(mm_kg_ms.to_si(dimension::kForce), 1e3);
    expect_relative(mm_kg_ms.to_si(dimension::kPressure), 1e9);
    expect_relative(units("mm-g-ms").to_si(dimension::kPressure), 1e6);  // MPa
    expect_relative(units("cm-g-us").to_si(dimension::kPressure), 1e11); // Mbar
    expect_relative(units("mm-N-s").mass, 1e3);                          // = mm-t-s
    // 1 lbf s^2/in = 4.4482216152605 N / 0.0254 m = 175.126835 kg; the slug 14.5939029 kg.
    expect_relative(units("in-lbf-s").mass, 4.4482216152605 / 0.0254);
    expect_relative(units("in-lbf-s").to_si(dimension::kPressure),
                    4.4482216152605 / 0.0254 / 0.0254);
    EXPECT_NEAR(units("ft-lbf-s").mass, 14.5939029, 1e-7);
    // The kip (1000 lbf) of the case files' unit table serves decks too: ksi stresses.
    expect_relative(units("in-kip-s").to_si(dimension::kPressure),
                    1e3 * 4.4482216152605 / 0.0254 / 0.0254);
    std::string error;
    EXPECT_FALSE(parse_keyword_units("mm-t", &error));
    EXPECT_NE(error.find("LENGTH-MASS-TIME"), std::string::npos);
    EXPECT_FALSE(parse_keyword_units("mm-s-t", &error));
    EXPECT_FALSE(parse_keyword_units("mm-furlong-s", &error));
    EXPECT_NE(error.find("\"furlong\" is not a unit"), std::string::npos) << error;
}

} // namespace
