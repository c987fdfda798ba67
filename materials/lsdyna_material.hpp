#pragma once

#include "io/keyword_deck.hpp"
#include "io/keyword_units.hpp"
#include "materials/cap_surfaces.hpp"
#include "materials/elastic_constants.hpp"
#include "materials/material.hpp"

#include <memory>
#include <string>
#include <string_view>

namespace grainload::io {
class CaseTable;
}

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

/// The [[material]] table's `from_lsdyna = {file = "sand.k", mid = 3, units = "mm-t-s"}`:
/// reads the deck and builds the GeneralizedCap. `model`, if given, must be
/// "generalized_cap"; keys the deck gives (density, the elastic pairs, cap_*) are refused. A
/// deck error becomes a io::CaseError at `from_lsdyna` carrying the deck's file, line and card.
std::unique_ptr<Material> material_from_lsdyna(const io::CaseTable& table);

} // namespace grainload::materials
