#include "io/units.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <string>

namespace grainload::io {

namespace {

struct UnitSymbol {
    std::string_view symbol;
    double factor;
    Dimension dimension;
    bool takes_prefix;
};

namespace dim = dimension;

// US customary units (exact by definition: 1 in = 0.0254 m, 1 ft = 0.3048 m, 1 lb = 0.45359237
// kg, 1 lbf = 1 lb x 9.80665 m/s^2), so that parameter sets ported from papers and LS-DYNA
// decks in the lbf-s-in and slug-ft-s systems can be written as given.
constexpr double kInch = 0.0254;
constexpr double kFoot = 0.3048;
constexpr double kPoundMass = 0.45359237;
constexpr double kPoundForce = kPoundMass * 9.80665;
constexpr double kPsi = kPoundForce / (kInch * kInch);

// Units a case file may use. SI prefixes apply to the ones marked; "kg" is kilo + "g".
constexpr std::array kUnits{
    UnitSymbol{"m", 1.0, dim::kLength, true},
    UnitSymbol{"g", 1e-3, dim::kMass, true},
    UnitSymbol{"s", 1.0, dim::kTime, true},
    UnitSymbol{"Pa", 1.0, dim::kPressure, true},
    UnitSymbol{"N", 1.0, dim::kForce, true},
    UnitSymbol{"J", 1.0, dim::kEnergy, true},
    UnitSymbol{"W", 1.0, Dimension{1, 2, -3, 0}, true},
    UnitSymbol{"Hz", 1.0, dim::kFrequency, true},
    UnitSymbol{"rad", 1.0, dim::kAngle, true},
    UnitSymbol{"deg", 3.14159265358979323846 / 180.0, dim::kAngle, false},
    UnitSymbol{"min", 60.0, dim::kTime, false},
    UnitSymbol{"h", 3600.0, dim::kTime, false},
    UnitSymbol{"t", 1e3, dim::kMass, false},
    // bar takes prefixes for the Mbar of the g-cm-us system of LS-DYNA decks.
    UnitSymbol{"bar", 1e5, dim::kPressure, true},
    UnitSymbol{"dyn", 1e-5, dim::kForce, false},
    UnitSymbol{"in", kInch, dim::kLength, false},
    UnitSymbol{"ft", kFoot, dim::kLength, false},
    UnitSymbol{"lb", kPoundMass, dim::kMass, false},
    UnitSymbol{"slug", kPoundForce / kFoot, dim::kMass, false},
    UnitSymbol{"lbf", kPoundForce, dim::kForce, false},
    UnitSymbol{"kip", 1e3 * kPoundForce, dim::kForce, false},
    UnitSymbol{"psi", kPsi, dim::kPressure, false},
    UnitSymbol{"ksi", 1e3 * kPsi, dim::kPressure, false},
    UnitSymbol{"psf", kPoundForce / (kFoot * kFoot), dim::kPressure, false},
};

struct Prefix {
    std::string_view symbol;
    double factor;
};

constexpr std::array kPrefixes{
    Prefix{"G", 1e9},  Prefix{"M", 1e6},  Prefix{"k", 1e3},  Prefix{"c", 1e-2},
    Prefix{"m", 1e-3}, Prefix{"u", 1e-6}, Prefix{"µ", 1e-6}, Prefix{"n", 1e-9},
};

std::optional<Quantity> lookup_symbol(std::string_view symbol) {
    for (const auto& unit : kUnits) {
        if (unit.symbol == symbol) {
            return Quantity{unit.factor, unit.dimension};
        }
    }
    for (const auto& prefix : kPrefixes) {
        if (!symbol.starts_with(prefix.symbol)) {
            continue;
        }
        const auto rest = symbol.substr(prefix.symbol.size());
        for (const auto& unit : kUnits) {
            // "cm" is the only centi- unit people write; "cs" or "cPa" are surely typos.
            const bool centi_ok = prefix.symbol != "c" || unit.symbol == "m";
            if (unit.takes_prefix && centi_ok && unit.symbol == rest) {
                return Quantity{prefix.factor * unit.factor, unit.dimension};
            }
        }
    }
    return std::nullopt;
}

bool is_symbol_char(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) != 0 || (c & 0x80) != 0;
}

// One factor of a unit expression: a symbol with an optional integer power, or "1".
bool parse_factor(std::string_view text, std::size_t& pos, Quantity& factor, std::string* error) {
    const std::size_t start = pos;
    if (text[pos] == '1') {
        ++pos;
        factor = Quantity{1.0, dim::kNone};
        return true;
    }
    while (pos < text.size() && is_symbol_char(text[pos])) {
        ++pos;
    }
    const auto symbol = text.substr(start, pos - start);
    const auto unit = symbol.empty() ? std::nullopt : lookup_symbol(symbol);
    if (!unit) {
        *error = "unknown unit '" + std::string(symbol.empty() ? text.substr(start) : symbol) + "'";
        return false;
    }
    int power = 1;
    if (pos < text.size() && text[pos] == '^') {
        ++pos;
        const auto [end, ec] = std::from_chars(text.data() + pos, text.data() + text.size(), power);
        if (ec != std::errc() || power == 0) {
            *error = "expected a non-zero integer power after '^' in '" + std::string(text) + "'";
            return false;
        }
        pos = static_cast<std::size_t>(end - text.data());
    }
    factor = Quantity{std::pow(unit->value, power), unit->dimension.power(power)};
    return true;
}

std::string_view trim(std::string_view text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) {
        return {};
    }
    const auto last = text.find_last_not_of(" \t");
    return text.substr(first, last - first + 1);
}

// A number at the start of `text`; returns the characters consumed, 0 when none.
std::size_t parse_number(std::string_view text, double& value) {
    const char* begin = text.data();
    if (!text.empty() && text.front() == '+') {
        ++begin;
    }
    const auto [end, ec] =
        std::from_chars(begin, text.data() + text.size(), value, std::chars_format::general);
    if (ec != std::errc() || !std::isfinite(value)) {
        return 0;
    }
    return static_cast<std::size_t>(end - text.data());
}

} // namespace

std::optional<Quantity> parse_unit(std::string_view text, std::string* error) {
    text = trim(text);
    Quantity total{1.0, dim::kNone};
    if (text.empty()) {
        return total;
    }
    std::size_t pos = 0;
    bool divide = false;
    while (pos < text.size()) {
        Quantity factor;
        if (!parse_factor(text, pos, factor, error)) {
            return std::nullopt;
        }
        total.value = divide ? total.value / factor.value : total.value * factor.value;
        total.dimension = total.dimension * factor.dimension.power(divide ? -1 : 1);
        while (pos < text.size() && text[pos] == ' ') {
            ++pos;
        }
        if (pos == text.size()) {
            break;
        }
        divide = text[pos] == '/';
        if (text[pos] == '/' || text[pos] == '*' || text[pos] == '.') {
            ++pos;
        } else if (text.substr(pos).starts_with("·")) {
            pos += std::string_view("·").size();
        }
        while (pos < text.size() && text[pos] == ' ') {
            ++pos;
        }
        if (pos == text.size()) {
            *error = "unit '" + std::string(text) + "' ends with an operator";
            return std::nullopt;
        }
    }
    return total;
}

std::optional<std::vector<Quantity>> parse_quantity_list(std::string_view text,
                                                         std::string* error) {
    std::string_view rest = trim(text);
    std::vector<double> numbers;
    while (!rest.empty()) {
        double value = 0.0;
        const std::size_t used = parse_number(rest, value);
        // In "9 1/MPa" the "1" opens the unit, it is not a second number.
        if (used == 0 || (!numbers.empty() && rest.substr(used).starts_with("/"))) {
            break;
        }
        numbers.push_back(value);
        rest = rest.substr(used);
        const bool separated = rest.empty() || rest.front() == ' ' || rest.front() == ',';
        if (!separated) {
            break;
        }
        rest = trim(rest);
        if (!rest.empty() && rest.front() == ',') {
            rest = trim(rest.substr(1));
        }
    }
    if (numbers.empty()) {
        *error = "expected a number followed by a unit, got '" + std::string(text) + "'";
        return std::nullopt;
    }
    const auto unit = parse_unit(rest, error);
    if (!unit) {
        return std::nullopt;
    }
    std::vector<Quantity> quantities;
    for (double number : numbers) {
        quantities.push_back(Quantity{number * unit->value, unit->dimension});
    }
    return quantities;
}

std::optional<Quantity> parse_quantity(std::string_view text, std::string* error) {
    auto list = parse_quantity_list(text, error);
    if (!list) {
        return std::nullopt;
    }
    if (list->size() != 1) {
        *error = "expected one number, got " + std::to_string(list->size()) + " in '" +
                 std::string(text) + "'";
        return std::nullopt;
    }
    return list->front();
}

} // namespace grainload::io
