#include "materials/lsdyna_material.hpp"

#include "io/keyword_fields.hpp"
#include "materials/generalized_cap.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

namespace grainload::materials {

namespace {

namespace dim = io::dimension;
using io::CardFields;
using io::FieldSpec;
using io::Keyword;
using io::KeywordCard;
using io::KeywordError;

// MAT_025's three cards, 10 columns a field (LS-DYNA Keyword User's Manual Vol. II; pydyna's
// mat_geologic_cap_model.py gives the same names, offsets 0, 10, ... 70 and widths 10).
constexpr std::array<FieldSpec, 8> kCard1{{{"MID", 10},
                                           {"RO", 10},
                                           {"BULK", 10},
                                           {"G", 10},
                                           {"ALPHA", 10},
                                           {"THETA", 10},
                                           {"GAMMA", 10},
                                           {"BETA", 10}}};
constexpr std::array<FieldSpec, 6> kCard2{
    {{"R", 10}, {"D", 10}, {"W", 10}, {"X0", 10}, {"C", 10}, {"N", 10}}};
constexpr std::array<FieldSpec, 4> kCard3{{{"PLOT", 10}, {"FTYPE", 10}, {"VEC", 10}, {"TOFF", 10}}};
// The first field of every *MAT_ card 1 is the material's MID.
constexpr std::array<FieldSpec, 1> kMidOnly{{{"MID", 10}}};

enum Card1 : std::size_t { kMid, kRo, kBulk, kShear, kAlpha, kTheta, kGamma, kBeta };
enum Card2 : std::size_t { kR, kD, kW, kX0, kC, kN };
enum Card3 : std::size_t { kPlot, kFtype, kVec, kToff };

bool is_mat025(const Keyword& keyword) {
    for (const std::string_view name : {"MAT_GEOLOGIC_CAP_MODEL", "MAT_025"}) {
        if (keyword.name == name || keyword.name == std::string(name) + "_TITLE") {
            return true;
        }
    }
    return false;
}

std::optional<long long> as_integer(std::string_view text) {
    long long value = 0;
    const char* first = text.data() + (text.starts_with('+') ? 1 : 0);
    const auto [end, error] = std::from_chars(first, text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) {
        return std::nullopt;
    }
    return value;
}

/// Whether a MID field names `mid`: as integers when both are ("3" and "03"), else as text.
bool same_id(std::string_view field, std::string_view mid) {
    const auto a = as_integer(field);
    const auto b = as_integer(mid);
    return a && b ? *a == *b : field == mid;
}

/// The cards of a keyword after its title card, if it has one.
std::vector<const KeywordCard*> data_cards(const Keyword& keyword) {
    std::vector<const KeywordCard*> cards;
    for (std::size_t i = keyword.has_title() ? 1 : 0; i < keyword.cards.size(); ++i) {
        cards.push_back(&keyword.cards[i]);
    }
    return cards;
}

/// One MAT_025 card group (3 cards, or 2 with card 3 left at its defaults).
struct Group {
    const Keyword* keyword = nullptr;
    const KeywordCard* cards[3] = {nullptr, nullptr, nullptr};
};

/// MAT_025 may repeat its card groups under one keyword; a lone group may omit card 3.
std::vector<Group> groups_of(const Keyword& keyword) {
    const auto cards = data_cards(keyword);
    if (cards.size() != 2 && (cards.empty() || cards.size() % 3 != 0)) {
        throw KeywordError(keyword.where() + ": expected 3 cards per material (MID RO BULK G " +
                           "ALPHA THETA GAMMA BETA / R D W X0 C N / PLOT FTYPE VEC TOFF), or " +
                           "cards 1 and 2 alone, got " + std::to_string(cards.size()));
    }
    std::vector<Group> groups;
    for (std::size_t i = 0; i < cards.size(); i += 3) {
        Group group{&keyword,
                    {cards[i], cards[i + 1], i + 2 < cards.size() ? cards[i + 2] : nullptr}};
        groups.push_back(group);
    }
    return groups;
}

/// The MAT_025 group of `mid`; refuses none, two, or a material of that id of another type.
Group find_group(const io::KeywordDeck& deck, std::string_view mid) {
    std::optional<Group> found;
    std::string others;
    for (const Keyword& keyword : deck.keywords) {
        if (!keyword.name.starts_with("MAT_") || keyword.name.starts_with("MAT_THERMAL_")) {
            continue;
        }
        if (is_mat025(keyword)) {
            for (const Group& group : groups_of(keyword)) {
                const CardFields fields(keyword, *group.cards[0], kCard1);
                if (!same_id(fields.text(kMid), mid)) {
                    continue;
                }
                if (found) {
                    fields.fail(kMid, "material " + std::string(mid) + " is defined twice (first " +
                                          found->keyword->where(*found->cards[0]) + ")");
                }
                found = group;
            }
            continue;
        }
        const auto cards = data_cards(keyword);
        if (cards.empty() || !same_id(CardFields(keyword, *cards[0], kMidOnly).text(0), mid)) {
            continue;
        }
        if (keyword.name.starts_with("MAT_ADD_")) {
            throw KeywordError(keyword.where(*cards[0]) + ": *" + keyword.name + " for material " +
                               std::string(mid) +
                               " changes its response (erosion, damage, ...), which grainload "
                               "does not implement; remove it");
        }
        others += "; material " + std::string(mid) + " is " + keyword.where() +
                  ", a model grainload does not read from decks";
    }
    if (!found) {
        const std::string file = deck.keywords.empty() ? "the deck" : deck.keywords.front().file;
        throw KeywordError(file + ": no *MAT_GEOLOGIC_CAP_MODEL (*MAT_025) with MID " +
                           std::string(mid) + others);
    }
    if (!others.empty()) {
        throw KeywordError(found->keyword->where(*found->cards[0]) + ": material " +
                           std::string(mid) + " is defined twice" + others);
    }
    return *found;
}

/// A field that must hold one of `allowed` integer values (MAT_025 writes flags as reals).
int flag(const CardFields& fields, std::size_t i, double fallback,
         std::initializer_list<int> allowed, std::string_view meaning) {
    const double value = fields.real_or(i, fallback);
    for (const int a : allowed) {
        if (value == static_cast<double>(a)) {
            return a;
        }
    }
    fields.fail(i, std::string(meaning));
}

/// Card 3's flags: only those whose meaning grainload implements or makes moot.
double read_card3(const Keyword& keyword, const KeywordCard* card, const io::KeywordUnits& units) {
    if (card == nullptr) {
        return 0.0;
    }
    const CardFields fields(keyword, *card, kCard3);
    flag(fields, kPlot, 1.0, {1, 2, 3, 4, 5, 8},
         "PLOT chooses what LS-DYNA writes; grainload writes the hardening parameter (1), cap "
         "position (2), plastic volumetric strain (3), the stress (4, 5) and the region (8) "
         "always, and has no equivalent of 6, 7 (unused) or 9 (iteration count)");
    flag(fields, kFtype, 1.0, {1},
         "only FTYPE = 1 (soil/concrete: the cap contracts with dilatancy) is implemented; "
         "FTYPE = 2 (rock: the cap never contracts) is not");
    // VEC = 0 stops LS-DYNA's return after a fixed number of iterations, VEC = 1 iterates to
    // convergence; grainload always converges, which VEC = 0 approximates.
    flag(fields, kVec, 0.0, {0, 1}, "expected VEC = 0 (vectorized) or 1 (fully iterative)");
    const double toff = fields.real_or(kToff, 0.0) * units.to_si(dim::kPressure);
    if (!(toff <= 0.0)) {
        fields.fail(kToff, "expected TOFF <= 0: the tension cutoff is the lowest I1, compression "
                           "positive");
    }
    return -toff;
}

double positive(const CardFields& fields, std::size_t i, double to_si) {
    const double value = fields.real(i);
    if (!(value > 0.0)) {
        fields.fail(i, "expected a value > 0");
    }
    return value * to_si;
}

/// The card field of a GeneralizedCap::check key.
std::pair<int, std::size_t> field_of(const std::string& key) {
    static const std::array<std::pair<const char*, std::pair<int, std::size_t>>, 9> kFields{{
        {"cap_k", {0, kAlpha}},
        {"cap_theta", {0, kTheta}},
        {"cap_gamma", {0, kGamma}},
        {"cap_beta", {0, kBeta}},
        {"cap_R", {1, kR}},
        {"cap_D", {1, kD}},
        {"cap_W", {1, kW}},
        {"cap_X0", {1, kX0}},
        {"tension_cutoff", {2, kToff}},
    }};
    for (const auto& [name, field] : kFields) {
        if (key == name) {
            return field;
        }
    }
    return {0, kMid};
}

std::string number_text(double value, int digits) {
    std::ostringstream out;
    out.precision(digits);
    out << value;
    return out.str();
}

/// A pressure in the unit of its size: "30.6 GPa".
std::string pressure_text(double pascal) {
    static constexpr std::array<std::pair<double, const char*>, 3> kUnits{
        {{1e9, "GPa"}, {1e6, "MPa"}, {1e3, "kPa"}}};
    for (const auto& [size, unit] : kUnits) {
        if (std::abs(pascal) >= size) {
            return number_text(pascal / size, 3) + " " + unit;
        }
    }
    return number_text(pascal, 3) + " Pa";
}

} // namespace

std::string implausible_values(const Mat025Material& m, const io::KeywordUnits& units) {
    struct Quantity {
        const char* name;
        double value; // SI
        io::Dimension dimension;
        double least;
        double most;
    };
    const std::array<Quantity, 3> quantities{{
        {"density", m.elastic.density, dim::kDensity, kLeastDensity, kMostDensity},
        {"bulk modulus", m.elastic.bulk_modulus, dim::kPressure, kLeastModulus, kMostModulus},
        {"shear modulus", m.elastic.shear_modulus, dim::kPressure, kLeastModulus, kMostModulus},
    }};
    auto inside = [](const Quantity& q, double value) {
        return value >= q.least && value <= q.most;
    };
    std::string odd;
    for (const Quantity& q : quantities) {
        if (!inside(q, q.value)) {
            const bool density = q.dimension == dim::kDensity;
            odd += std::string(odd.empty() ? "" : ", ") + "its " + q.name + " " +
                   number_text(q.value, 4) + (density ? " kg/m^3" : " Pa") + " is outside " +
                   (density ? "100 to 25000 kg/m^3" : "0.1 MPa to 1000 GPa");
        }
    }
    if (odd.empty()) {
        return "";
    }
    odd = "read in \"" + units.name + "\" " + odd;
    static constexpr std::array<const char*, 8> kCommon{
        "m-kg-s", "mm-t-s", "mm-kg-ms", "mm-g-ms", "cm-g-us", "cm-g-s", "in-lbf-s", "ft-lbf-s"};
    for (const char* name : kCommon) {
        std::string error;
        const auto other = io::parse_keyword_units(name, &error);
        std::array<double, 3> values{};
        bool fits = other.has_value();
        for (std::size_t k = 0; k < quantities.size() && fits; ++k) {
            const Quantity& q = quantities[k];
            values[k] = q.value / units.to_si(q.dimension) * other->to_si(q.dimension);
            fits = inside(q, values[k]);
        }
        if (fits) {
            return odd + "; read in \"" + std::string(name) + "\" they are " +
                   number_text(values[0], 4) + " kg/m^3, " + pressure_text(values[1]) + " and " +
                   pressure_text(values[2]);
        }
    }
    return odd;
}

Mat025Material read_mat025(const io::KeywordDeck& deck, std::string_view mid,
                           const io::KeywordUnits& units) {
    const Group group = find_group(deck, mid);
    const Keyword& keyword = *group.keyword;
    const CardFields card1(keyword, *group.cards[0], kCard1);
    const CardFields card2(keyword, *group.cards[1], kCard2);
    const double pressure = units.to_si(dim::kPressure);
    const double inverse_pressure = units.to_si(dim::kInversePressure);
    for (const std::size_t i : {kC, kN}) {
        if (card2.real_or(i, 0.0) != 0.0) {
            card2.fail(i, "C and N drive kinematic hardening of the failure envelope, which "
                          "grainload does not implement (C = 0 and N = 0, or blank, mean none)");
        }
    }
    Mat025Material m;
    m.where = keyword.where();
    m.file = keyword.file;
    m.line = keyword.line;
    m.elastic = ElasticConstants::from_bulk_shear(positive(card1, kRo, units.to_si(dim::kDensity)),
                                                  positive(card1, kBulk, pressure),
                                                  positive(card1, kShear, pressure));
    cap::Parameters& p = m.parameters;
    p.k = card1.real_or(kAlpha, 0.0) * pressure;
    p.theta = card1.real_or(kTheta, 0.0);
    p.gamma = card1.real_or(kGamma, 0.0) * pressure;
    p.beta = card1.real_or(kBeta, 0.0) * inverse_pressure;
    p.R = card2.real_or(kR, 0.0);
    p.D = card2.real_or(kD, 0.0) * inverse_pressure;
    p.W = card2.real_or(kW, 0.0);
    p.X0 = card2.real_or(kX0, 0.0) * pressure;
    p.tension = read_card3(keyword, group.cards[2], units);
    p.semantics = cap::Semantics::mat025;
    if (const auto [key, message] = GeneralizedCap::check(p); !key.empty()) {
        const auto [card, field] = field_of(key);
        if (card == 2 && group.cards[2] != nullptr) {
            CardFields(keyword, *group.cards[2], kCard3).fail(field, message);
        }
        (card == 1 ? card2 : card1).fail(field, message);
    }
    return m;
}

} // namespace grainload::materials
