#include "io/keyword_units.hpp"

#include "io/units.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace grainload::io {

namespace {

namespace dim = dimension;

std::vector<std::string_view> split(std::string_view text) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find('-', start);
        parts.push_back(text.substr(start, end == std::string_view::npos ? end : end - start));
        if (end == std::string_view::npos) {
            return parts;
        }
        start = end + 1;
    }
}

} // namespace

double KeywordUnits::to_si(const Dimension& d) const {
    return std::pow(mass, d.mass) * std::pow(length, d.length) * std::pow(time, d.time);
}

std::optional<KeywordUnits> parse_keyword_units(std::string_view text, std::string* error) {
    const std::string expected =
        "expected LENGTH-MASS-TIME or LENGTH-FORCE-TIME, e.g. \"m-kg-s\", \"mm-t-s\", "
        "\"mm-kg-ms\", \"in-lbf-s\"";
    const auto parts = split(text);
    if (parts.size() != 3) {
        *error = expected + ", got \"" + std::string(text) + "\"";
        return std::nullopt;
    }
    std::array<Quantity, 3> units;
    for (std::size_t k = 0; k < 3; ++k) {
        std::string why;
        const auto unit = parts[k].empty() ? std::nullopt : parse_unit(parts[k], &why);
        if (!unit) {
            *error = expected + ": \"" + std::string(parts[k]) + "\" is not a unit" +
                     (why.empty() ? "" : " (" + why + ")");
            return std::nullopt;
        }
        units[k] = *unit;
    }
    const bool force = units[1].dimension == dim::kForce;
    if (units[0].dimension != dim::kLength || units[2].dimension != dim::kTime ||
        !(force || units[1].dimension == dim::kMass)) {
        *error = expected + ": \"" + std::string(text) + "\" is not length-mass-time";
        return std::nullopt;
    }
    KeywordUnits system;
    system.name = std::string(text);
    system.length = units[0].value;
    system.time = units[2].value;
    system.mass =
        force ? units[1].value * system.time * system.time / system.length : units[1].value;
    return system;
}

} // namespace grainload::io
