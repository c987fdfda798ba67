// The [[material]] key from_lsdyna: a *MAT_GEOLOGIC_CAP_MODEL (MAT_025) card of an LS-DYNA deck
// read into a GeneralizedCap. The reference is the same material given by cap_* keys (the thesis
// wagon set of section 7.4, cases/matpoint/oedometer_cap_wagon.toml, and the ksi sand of the
// user guide): the same parameters after unit conversion and the same response on the
// material-point driver. Hand-written decks in fixed, free and long format; every refusal names
// the deck's file, line, card and field.

#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "io/keyword_deck.hpp"
#include "materials/generalized_cap.hpp"
#include "materials/lsdyna_material.hpp"
#include "materials/material_case_reader.hpp"
#include "materials/material_point_reader.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <tuple>
#include <unistd.h>
#include <vector>

namespace grainload::materials {
namespace {

namespace fs = std::filesystem;

// Unit conversion multiplies a deck number by a product of powers of the deck's units (e.g.
// 1e3 kg * (1e-3 m)^-1 s^-2 for MPa) where a case key multiplies it by the unit's factor (1e6):
// the two may differ in the last bits, a few ulp, never more.
constexpr double kConversionTolerance = 1e-14;
// The driver's response is a smooth function of the parameters except at region changes, which
// a few-ulp change of a parameter does not move on this path: stresses agree to round-off of the
// return mapping's Newton solves (their tolerance is 1e-12 relative, cap_return.cpp).
constexpr double kResponseTolerance = 1e-10;

/// A fixed-format card: each field right-aligned in 10 columns (MAT_025's width).
std::string card(const std::vector<std::string>& fields, int width = 10) {
    std::string out;
    for (const auto& f : fields) {
        out += std::string(
                   static_cast<std::size_t>(std::max(0, width - static_cast<int>(f.size()))), ' ') +
               f;
    }
    return out;
}

/// The wagon set of thesis section 7.4 in mm-t-s (MPa), as MAT_025 cards 1-3.
const std::vector<std::string> kWagon1{"3",       "2.099E-9", "30620.0", "8230.0",
                                       "0.00106", "0.004",    "0.0",     "1.0"};
const std::vector<std::string> kWagon2{"2.0", "7.25", "2.58", "0.0", "0.0", "0.0"};
const std::vector<std::string> kWagon3{"1.0", "1.0", "0.0", "0.0"};

/// The wagon deck without *END, so that a test may add keywords after it.
std::string wagon_cards(const std::vector<std::string>& c1 = kWagon1,
                        const std::vector<std::string>& c2 = kWagon2,
                        const std::vector<std::string>& c3 = kWagon3) {
    return "*KEYWORD\n*MAT_GEOLOGIC_CAP_MODEL_TITLE\nwagon sand\n$ comment\n" + card(c1) + "\n" +
           card(c2) + "\n" + card(c3) + "\n";
}

std::string wagon_deck(const std::vector<std::string>& c1 = kWagon1,
                       const std::vector<std::string>& c2 = kWagon2,
                       const std::vector<std::string>& c3 = kWagon3) {
    return wagon_cards(c1, c2, c3) + "*END\n";
}

io::KeywordDeck deck_of(const std::string& text) {
    std::istringstream in(text);
    return io::read_keyword_deck(in, "deck.k", ".");
}

io::KeywordUnits units(const char* name) {
    std::string error;
    return *io::parse_keyword_units(name, &error);
}

/// The message of the KeywordError read_mat025 throws, or "no error".
std::string deck_error(const std::string& text, const char* mid = "3") {
    try {
        read_mat025(deck_of(text), mid, units("mm-t-s"));
    } catch (const io::KeywordError& e) {
        return e.what();
    }
    return "no error";
}

/// A temporary directory holding a case file and its deck.
class CaseDir {
  public:
    CaseDir()
        : dir_(fs::temp_directory_path() / ("grainload_lsdyna_" + std::to_string(::getpid()))) {
        fs::create_directories(dir_);
    }
    ~CaseDir() { fs::remove_all(dir_); }
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(dir_ / name) << text;
        return (dir_ / name).string();
    }

  private:
    fs::path dir_;
};

/// The first material of a case file, read as a scene reads it (name included).
std::unique_ptr<Material> material_of(const std::string& case_file) {
    auto document = io::CaseDocument::from_file(case_file);
    const io::CaseTable table = document->root().array_of_tables("material").front();
    table.string("name");
    auto m = read_material(table);
    document->reject_unknown_keys();
    return m;
}

/// The error a case with this [[material]] body (and wagon.k holding `deck`) gives.
std::string case_error(const std::string& body, const std::string& deck = wagon_deck()) {
    CaseDir dir;
    dir.write("wagon.k", deck);
    try {
        material_of(dir.write("case.toml", "[[material]]\nname = \"sand\"\n" + body));
    } catch (const io::CaseError& e) {
        return e.what();
    }
    return "no error";
}

void expect_close(double a, double b, double tolerance, const char* what) {
    EXPECT_LE(std::abs(a - b), tolerance * std::abs(b)) << what << ": " << a << " vs " << b;
}

void expect_same_parameters(const GeneralizedCap& a, const GeneralizedCap& b) {
    const auto& p = a.parameters();
    const auto& q = b.parameters();
    for (const auto& [x, y, name] : {std::tuple{p.k, q.k, "k"},
                                     {p.theta, q.theta, "theta"},
                                     {p.gamma, q.gamma, "gamma"},
                                     {p.beta, q.beta, "beta"},
                                     {p.D, q.D, "D"},
                                     {p.W, q.W, "W"},
                                     {p.X0, q.X0, "X0"},
                                     {p.R, q.R, "R"},
                                     {p.tension, q.tension, "T"}}) {
        expect_close(x, y, kConversionTolerance, name);
    }
    EXPECT_EQ(p.semantics, q.semantics);
    expect_close(a.density(), b.density(), kConversionTolerance, "density");
    expect_close(a.elastic().bulk_modulus, b.elastic().bulk_modulus, kConversionTolerance, "K");
    expect_close(a.elastic().shear_modulus, b.elastic().shear_modulus, kConversionTolerance, "G");
}

TEST(LsdynaMaterial, WagonSetInMillimetreTonneSecondIsTheThesisSetInSi) {
    const Mat025Material m = read_mat025(deck_of(wagon_deck()), "3", units("mm-t-s"));
    // Thesis 7.4 in SI: 1 MPa = 1e6 Pa, 1 t/mm^3 = 1e12 kg/m^3.
    expect_close(m.elastic.density, 2099.0, kConversionTolerance, "rho");
    expect_close(m.elastic.bulk_modulus, 30.62e9, kConversionTolerance, "K");
    expect_close(m.elastic.shear_modulus, 8.23e9, kConversionTolerance, "G");
    expect_close(m.parameters.k, 1060.0, kConversionTolerance, "k");
    expect_close(m.parameters.beta, 1e-6, kConversionTolerance, "B1");
    expect_close(m.parameters.D, 7.25e-6, kConversionTolerance, "D");
    EXPECT_EQ(m.parameters.theta, 0.004);
    EXPECT_EQ(m.parameters.W, 2.58);
    EXPECT_EQ(m.parameters.R, 2.0);
    EXPECT_EQ(m.parameters.X0, 0.0);
    EXPECT_EQ(m.parameters.gamma, 0.0);
    EXPECT_EQ(m.parameters.tension, 0.0);
    EXPECT_EQ(m.parameters.semantics, cap::Semantics::mat025);
}

// A deck read in other units than its own leaves the ranges of a granular material. The wagon
// set (mm-t-s) read as m-kg-s: rho = 2.099e-9 kg/m^3, K = 30620 Pa, G = 8230 Pa, all three
// outside; the first common system that puts them inside is its own, where they are the thesis'
// 2099 kg/m^3, 30.62 GPa and 8.23 GPa. Read as mm-kg-ms (kg/mm^3 = 1e9 kg/m^3, GPa) its density
// is 2.099 kg/m^3 and its moduli 3.1e13 and 8.2e12 Pa: outside too. In its own units, nothing.
TEST(LsdynaMaterial, ValuesOutsideTheGranularRangesNameTheUnitsThatFit) {
    const io::KeywordDeck deck = deck_of(wagon_deck());
    EXPECT_EQ(implausible_values(read_mat025(deck, "3", units("mm-t-s")), units("mm-t-s")), "");
    const io::KeywordUnits si = units("m-kg-s");
    EXPECT_EQ(implausible_values(read_mat025(deck, "3", si), si),
              "read in \"m-kg-s\" its density 2.099e-09 kg/m^3 is outside 100 to 25000 kg/m^3, "
              "its bulk modulus 3.062e+04 Pa is outside 0.1 MPa to 1000 GPa, its shear modulus "
              "8230 Pa is outside 0.1 MPa to 1000 GPa; read in \"mm-t-s\" they are 2099 kg/m^3, "
              "30.6 GPa and 8.23 GPa");
    const io::KeywordUnits giga = units("mm-kg-ms");
    const std::string odd = implausible_values(read_mat025(deck, "3", giga), giga);
    EXPECT_NE(odd.find("its density 2.099 kg/m^3 is outside"), std::string::npos) << odd;
    EXPECT_NE(odd.find("its bulk modulus 3.062e+13 Pa is outside"), std::string::npos) << odd;
    EXPECT_NE(odd.find("read in \"mm-t-s\" they are 2099 kg/m^3"), std::string::npos) << odd;
}

TEST(LsdynaMaterial, FreeLongAndAliasFormsReadTheSameMaterial) {
    const auto reference = read_mat025(deck_of(wagon_deck()), "3", units("mm-t-s"));
    const std::string free_format = "*KEYWORD\n*MAT_025\n3, 2.099e-9, 30620, 8230, 0.00106, "
                                    "0.004, , 1.0\n2.0,7.25,2.58,0,0,0\n1,1,0,0\n";
    // LONG=Y: every field 20 columns. Card 3 left out: PLOT, FTYPE, VEC, TOFF at defaults.
    const std::string long_format = "*KEYWORD LONG=Y\n*MAT_GEOLOGIC_CAP_MODEL\n" +
                                    card(kWagon1, 20) + "\n" + card(kWagon2, 20) + "\n";
    for (const std::string& text : {free_format, long_format}) {
        const auto m = read_mat025(deck_of(text), "3", units("mm-t-s"));
        EXPECT_EQ(m.elastic.density, reference.elastic.density) << text;
        EXPECT_EQ(m.elastic.bulk_modulus, reference.elastic.bulk_modulus);
        EXPECT_EQ(m.parameters.k, reference.parameters.k);
        EXPECT_EQ(m.parameters.D, reference.parameters.D);
        EXPECT_EQ(m.parameters.W, reference.parameters.W);
        EXPECT_EQ(m.parameters.tension, 0.0);
    }
}

TEST(LsdynaMaterial, PicksItsMaterialAmongOthers) {
    auto c1 = kWagon1;
    c1[0] = "7";
    c1[2] = "1000.0"; // a different K for MID 7
    const std::string text = "*KEYWORD\n*MAT_ELASTIC\n         1    7.8E-9  210000.0       0.3\n"
                             "*MAT_GEOLOGIC_CAP_MODEL\n" +
                             card(kWagon1) + "\n" + card(kWagon2) + "\n" + card(kWagon3) +
                             "\n*MAT_GEOLOGIC_CAP_MODEL\n" + card(c1) + "\n" + card(kWagon2) +
                             "\n*END\n";
    EXPECT_EQ(read_mat025(deck_of(text), "7", units("mm-t-s")).elastic.bulk_modulus, 1e9);
    EXPECT_EQ(read_mat025(deck_of(text), "03", units("mm-t-s")).elastic.bulk_modulus, 30.62e9);
}

TEST(LsdynaMaterial, SameResponseOnTheMaterialPointDriverAsTheCapKeys) {
    // cases/matpoint: the oedometer of the wagon set from cap_* keys and from wagon_sand.k.
    const std::string dir = std::string(GRAINLOAD_SOURCE_DIR) + "/cases/matpoint/";
    std::vector<std::vector<MaterialPointRecord>> runs;
    std::vector<std::unique_ptr<Material>> built;
    for (const char* file : {"oedometer_cap_wagon.toml", "oedometer_cap_wagon_deck.toml"}) {
        auto document = io::CaseDocument::from_file(dir + file);
        const io::CaseTable root = document->root();
        built.push_back(read_material(root.array_of_tables("material").front()));
        const MaterialPointPath path = read_material_point_path(root.table("path"));
        runs.emplace_back();
        drive_material_point(*built.back(), path, runs.back());
    }
    expect_same_parameters(dynamic_cast<const GeneralizedCap&>(*built[1]),
                           dynamic_cast<const GeneralizedCap&>(*built[0]));
    ASSERT_EQ(runs[0].size(), runs[1].size());
    ASSERT_EQ(runs[0].size(), 31u);
    double scale = 0.0;
    for (const auto& r : runs[0]) {
        scale = std::max(scale, r.stress.cwiseAbs().maxCoeff());
    }
    for (std::size_t i = 0; i < runs[0].size(); ++i) {
        EXPECT_LE((runs[1][i].stress - runs[0][i].stress).cwiseAbs().maxCoeff(),
                  kResponseTolerance * scale)
            << "step " << i;
        EXPECT_EQ(runs[1][i].region, runs[0][i].region) << "step " << i;
    }
    // The path's own check (test_cap_uniaxial_strain): 357.1 Pa axial stress at 1 % strain.
    EXPECT_NEAR(-runs[1][10].stress(0), 357.1, 0.05);
}

TEST(LsdynaMaterial, KsiDeckEqualsTheUserGuideKeys) {
    // The user guide's MAT_025 sand in ksi (docs/user-guide.md), as keys and as an in-lbf-s deck
    // (density 1.684e-4 lbf s^2/in^4, stresses psi: the deck's numbers are 1000 times the ksi).
    const std::string keys =
        "model = \"generalized_cap\"\ndensity = \"1.684e-4 lbf*s^2/in^4\"\n"
        "bulk_modulus = \"66.7 ksi\"\nshear_modulus = \"40 ksi\"\ncap_alpha = \"0.25 ksi\"\n"
        "cap_theta = 0.0\ncap_gamma = \"0.18 ksi\"\ncap_beta = \"0.67 1/ksi\"\ncap_R = 2.5\n"
        "cap_D = \"0.67 1/ksi\"\ncap_W = 0.066\ncap_X0 = \"0.1 ksi\"\ncap_toff = \"0 ksi\"\n";
    const std::string deck =
        "*KEYWORD\n*MAT_GEOLOGIC_CAP_MODEL\n" +
        card({"1", "1.684E-4", "66700.", "40000.", "250.", "0.", "180.", "6.7E-4"}) + "\n" +
        card({"2.5", "6.7E-4", "0.066", "100.", "0.", "0."}) + "\n" + card({"1", "1", "1", "-0."}) +
        "\n";
    CaseDir dir;
    dir.write("sand.k", deck);
    const auto from_keys =
        material_of(dir.write("keys.toml", "[[material]]\nname = \"s\"\n" + keys));
    const auto from_deck = material_of(dir.write(
        "deck.toml", "[[material]]\nname = \"s\"\n"
                     "from_lsdyna = { file = \"sand.k\", mid = 1, units = \"in-lbf-s\" }\n"));
    expect_same_parameters(dynamic_cast<const GeneralizedCap&>(*from_deck),
                           dynamic_cast<const GeneralizedCap&>(*from_keys));
}

TEST(LsdynaMaterial, StiffnessScaleAppliesToTheDeckMaterial) {
    CaseDir dir;
    dir.write("wagon.k", wagon_deck());
    const auto m = material_of(dir.write(
        "case.toml", "[[material]]\nname = \"s\"\nstiffness_scale = 0.001\n"
                     "from_lsdyna = { file = \"wagon.k\", mid = 3, units = \"mm-t-s\" }\n"));
    expect_close(m->elastic().bulk_modulus, 30.62e6, kConversionTolerance, "K");
    expect_close(m->elastic().shear_modulus, 8.23e6, kConversionTolerance, "G");
    EXPECT_EQ(m->elastic().stiffness_scale, 0.001);
}

TEST(LsdynaMaterial, DeckRefusalsNameFileLineCardAndField) {
    struct Case {
        std::string deck;
        const char* mid;
        std::vector<std::string> expected;
    };
    auto with = [](std::vector<std::string> c, std::size_t i, const char* value) {
        c[i] = value;
        return c;
    };
    const std::vector<Case> cases{
        {wagon_deck(), "4", {"deck.k: no *MAT_GEOLOGIC_CAP_MODEL (*MAT_025) with MID 4"}},
        {wagon_deck(kWagon1, with(kWagon2, 4, "0.5")),
         "3",
         {"deck.k:6: *MAT_GEOLOGIC_CAP_MODEL_TITLE card", "field C (columns 41-50)",
          "kinematic hardening"}},
        {wagon_deck(kWagon1, with(kWagon2, 5, "2.0")), "3", {"field N (columns 51-60)"}},
        {wagon_deck(kWagon1, kWagon2, with(kWagon3, 1, "2.0")),
         "3",
         {"deck.k:7:", "field FTYPE (columns 11-20)", "rock"}},
        {wagon_deck(kWagon1, kWagon2, with(kWagon3, 0, "9.0")), "3", {"field PLOT", "iteration"}},
        {wagon_deck(kWagon1, kWagon2, with(kWagon3, 2, "2.0")), "3", {"field VEC"}},
        {wagon_deck(kWagon1, kWagon2, with(kWagon3, 3, "0.1")),
         "3",
         {"field TOFF (columns 31-40)", "TOFF <= 0"}},
        {wagon_deck(kWagon1, with(kWagon2, 1, "")), "3", {"deck.k:6:", "field D", "D > 0"}},
        {wagon_deck(with(kWagon1, 1, "")), "3", {"deck.k:5:", "field RO", "blank"}},
        {wagon_deck(with(kWagon1, 2, "-1.")), "3", {"field BULK", "> 0"}},
        {wagon_deck(kWagon1, with(kWagon2, 3, "-0.1")), "3", {"field X0", "X0 >="}},
        {wagon_cards() + "*MAT_GEOLOGIC_CAP_MODEL\n" + card(kWagon1) + "\n" + card(kWagon2) + "\n",
         "3",
         {"deck.k:9:", "defined twice (first deck.k:5:"}},
        {wagon_cards() + "*MAT_ELASTIC\n         3    7.8E-9  210000.0       0.3\n",
         "3",
         {"defined twice", "deck.k:8: *MAT_ELASTIC"}},
        {wagon_cards() + "*MAT_ADD_EROSION\n         3\n",
         "3",
         {"deck.k:9: *MAT_ADD_EROSION", "erosion"}},
        {"*MAT_GEOLOGIC_CAP_MODEL\n" + card(kWagon1) + "\n", "3", {"expected 3 cards"}},
    };
    for (const Case& c : cases) {
        const std::string message = deck_error(c.deck, c.mid);
        for (const std::string& part : c.expected) {
            EXPECT_NE(message.find(part), std::string::npos)
                << "expected \"" << part << "\" in: " << message;
        }
    }
}

TEST(LsdynaMaterial, CaseRefusals) {
    const std::string source =
        "from_lsdyna = { file = \"wagon.k\", mid = 3, units = \"mm-t-s\" }\n";
    const std::vector<std::pair<std::string, std::vector<std::string>>> cases{
        {"from_lsdyna = { file = \"wagon.k\", mid = 3 }\n",
         {"case.toml:3:", "material[0].from_lsdyna.units", "missing required key"}},
        {"from_lsdyna = { file = \"wagon.k\", mid = 3, units = \"mm-s\" }\n",
         {"from_lsdyna.units", "LENGTH-MASS-TIME"}},
        {"from_lsdyna = { file = \"missing.k\", mid = 3, units = \"mm-t-s\" }\n",
         {"from_lsdyna.file"}},
        {"from_lsdyna = { file = \"wagon.k\", mid = 5, units = \"mm-t-s\" }\n",
         {"from_lsdyna.file", "wagon.k", "with MID 5"}},
        {source + "cap_W = 0.1\n", {"material[0].cap_W", "the deck"}},
        {source + "density = \"1 kg/m^3\"\n", {"material[0].density", "the deck"}},
        {source + "model = \"drucker_prager\"\n", {"material[0].model", "generalized_cap"}},
        {source + "stiffness_scale = 0\n", {"stiffness_scale", "> 0"}},
    };
    for (const auto& [body, expected] : cases) {
        const std::string message = case_error(body);
        for (const std::string& part : expected) {
            EXPECT_NE(message.find(part), std::string::npos)
                << "expected \"" << part << "\" in: " << message;
        }
    }
    // A model key that says what the deck says is accepted.
    EXPECT_EQ(case_error(source + "model = \"generalized_cap\"\n"), "no error");
}

} // namespace
} // namespace grainload::materials
