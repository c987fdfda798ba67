#pragma once
// A *MAT_GEOLOGIC_CAP_MODEL (MAT_025) material read from an LS-DYNA deck, converted to SI.

#include "io/keyword_deck.hpp"
#include "io/keyword_units.hpp"
#include "materials/cap_surfaces.hpp"
#include "materials/elastic_constants.hpp"
#include "materials/material.hpp"

#include <memory>
#include <string>
#include <string_view>

namespace grainload::materials {

/// One *MAT_GEOLOGIC_CAP_MODEL (alias *MAT_025, both with an optional _TITLE) material of an
/// LS-DYNA keyword deck, converted to SI with the deck's unit system. Card layout (LS-DYNA
/// Keyword User's Manual Vol. II, MAT_025; field names, widths and defaults as in Ansys pydyna's
/// keyword class mat_geologic_cap_model.py): all fields 10 columns,
///   card 1: MID RO BULK G ALPHA THETA GAMMA BETA
///   card 2: R D W X0 C N
///   card 3: PLOT (1) FTYPE (1) VEC (0) TOFF
/// A blank field is 0 unless a default is shown; card 3 may be left out (all defaults).
struct Mat025Material {
    std::string where; ///< "file:line: *MAT_GEOLOGIC_CAP_MODEL", for messages
    std::string file;  ///< the file and line of its keyword (the deck or a file it includes)
    int line = 0;
    ElasticConstants elastic;
    cap::Parameters parameters; ///< MAT_025 semantics
};

/// Reads material `mid` (an integer id or, as LS-DYNA allows, a label; compared as integers
/// when both are integers) from `deck`. Refused with an io::KeywordError naming file, line,
/// card and field: no material of that id; two of them; a material of another *MAT_ type; a
/// *MAT_ADD_ keyword for it (erosion, damage, ... change the response); C or N nonzero
/// (kinematic hardening); FTYPE = 2 (rock); PLOT other than 1-5 or 8; VEC other than 0 or 1;
/// TOFF > 0; and every parameter GeneralizedCap::check refuses.
Mat025Material read_mat025(const io::KeywordDeck& deck, std::string_view mid,
                           const io::KeywordUnits& units);

/// The ranges of what a *MAT_GEOLOGIC_CAP_MODEL may describe, a soil, a bulk solid, rock or
/// concrete, wide enough that only a deck read in other units than its own leaves them (a
/// mismatch moves a density by 1e3 or more, e.g. 1e12 between mm-t-s and m-kg-s): densities
/// from the lightest bulk solids (expanded perlite, about 100 kg/m^3) to the densest metal
/// (osmium, 22 600 kg/m^3); bulk and shear moduli from a tenth of a loose soil's (a few MPa at
/// the surface) to twice diamond's bulk modulus (443 GPa).
inline constexpr double kLeastDensity = 100.0;  ///< kg/m^3
inline constexpr double kMostDensity = 25000.0; ///< kg/m^3
inline constexpr double kLeastModulus = 1e5;    ///< Pa
inline constexpr double kMostModulus = 1e12;    ///< Pa

/// "" when the material's density, bulk and shear moduli lie in the ranges above; else what
/// lies outside, in `units`, and the first unit system of the common ones (m-kg-s, mm-t-s,
/// mm-kg-ms, mm-g-ms, cm-g-us, cm-g-s, in-lbf-s, ft-lbf-s) that puts all three inside, with
/// their values there: "read in \"m-kg-s\" its density 2.099e-09 kg/m^3 is outside ...; read in
/// \"mm-t-s\" they are 2099 kg/m^3, 30.6 GPa and 8.23 GPa".
std::string implausible_values(const Mat025Material& material, const io::KeywordUnits& units);

} // namespace grainload::materials
