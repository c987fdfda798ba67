#include "materials/material_schema.hpp"

#include "materials/material_case_reader.hpp"
#include "materials/material_point_reader.hpp"

#include <array>

namespace grainload::materials {

namespace {

constexpr std::string_view kGuide = "docs/user-guide.md";

const std::array<io::KeyTable, 9> kTables{{
    {"material", true, "a material: its model, density and elastic constants", kMaterialKeys,
     kGuide, "## `[[material]]`"},
    {"material.von_mises", false, "von Mises plasticity with mixed linear hardening", kVonMisesKeys,
     kGuide, "### `von_mises`"},
    {"material.drucker_prager", false, "the Drucker-Prager cone with a tension cutoff",
     kDruckerPragerKeys, kGuide, "### `drucker_prager`"},
    {"material.generalized_cap", false, "the generalized cap model (LS-DYNA's MAT_025)",
     kGeneralizedCapKeys, kGuide, "### `generalized_cap`"},
    {"material.from_lsdyna", false, "a material read from an LS-DYNA deck's MAT_025 card",
     kFromLsDynaKeys, kGuide, "#### A material from an LS-DYNA deck (`from_lsdyna`)"},
    {"material.mu_i", false, "the rate-dependent friction mu(I) of dense granular flow", kMuIKeys,
     kGuide, "### `mu_i`"},
    {"material.mohr_coulomb", false, "the Mohr-Coulomb hexagon in 3D, corners returned exactly",
     kMohrCoulombKeys, kGuide, "### `mohr_coulomb`"},
    {"path", false, "a material-point driver file's path: initial stress and Newton settings",
     kPathKeys, "docs/user-guide/matpoint.md", "### `[path]`"},
    {"path.segment", true, "a material-point path's segment: strain- and stress-controlled parts",
     kSegmentKeys, "docs/user-guide/matpoint.md", "### `[[path.segment]]`"},
}};

} // namespace

std::span<const io::KeyTable> material_key_tables() {
    return kTables;
}

} // namespace grainload::materials
