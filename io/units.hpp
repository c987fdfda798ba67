#pragma once
// Quantities with units ("72 mm", "30.62 GPa") parsed and converted to SI.

#include "io/dimension.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace grainload::io {

/// A number with its dimension, already converted to SI (radians for angles).
struct Quantity {
    double value = 0.0;
    Dimension dimension;
};

/// Parse "72 mm", "30.62 GPa", "2099 kg/m^3", "9.81 m/s^2", "35 deg", "1/MPa", "0.3".
/// Returns std::nullopt and sets `error` when the text is not a quantity.
std::optional<Quantity> parse_quantity(std::string_view text, std::string* error);

/// Parse several numbers sharing one unit: "0 0 -9.81 m/s^2", "10, 20, 30 mm".
std::optional<std::vector<Quantity>> parse_quantity_list(std::string_view text, std::string* error);

/// Parse a unit expression alone ("kg/m^3", "MPa^-1"): its SI factor and dimension.
std::optional<Quantity> parse_unit(std::string_view text, std::string* error);

} // namespace grainload::io
