#pragma once
// The consistent unit system of an LS-DYNA deck, stated as "LENGTH-MASS-TIME".

#include "io/dimension.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace grainload::io {

/// The consistent unit system of an LS-DYNA deck, which the deck itself does not state: the SI
/// value of its length, mass and time units. Every other unit follows from these three (force
/// = mass length / time^2, stress = force / length^2, density = mass / length^3).
struct KeywordUnits {
    std::string name = "m-kg-s";
    double length = 1.0; ///< m per deck length unit
    double mass = 1.0;   ///< kg per deck mass unit
    double time = 1.0;   ///< s per deck time unit

    /// SI value of one deck unit of dimension `d` (angles pass unchanged).
    double to_si(const Dimension& d) const;
};

/// Parses "LENGTH-MASS-TIME", e.g. "m-kg-s", "mm-t-s" (N, MPa), "mm-kg-ms" (kN, GPa),
/// "mm-g-ms" (N, MPa), "cm-g-us" (Mbar). The middle unit may instead be a force, and the mass
/// unit is then the one that force makes consistent, force time^2 / length: "in-lbf-s" (the
/// "slinch", lbf s^2/in), "ft-lbf-s" (the slug), "mm-N-s" (= "mm-t-s"). Units are those of
/// case files (io/units.hpp, which include in, ft, lb, lbf and slug). Returns std::nullopt and
/// sets `error` when the text is not such a system.
std::optional<KeywordUnits> parse_keyword_units(std::string_view text, std::string* error);

} // namespace grainload::io
