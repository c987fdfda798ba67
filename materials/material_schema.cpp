#include "materials/material_schema.hpp"

#include "materials/mu_i_material.hpp"

#include <array>

namespace grainload::materials {

namespace {

const std::array<io::KeyTable, 1> kTables{{
    {"material.mu_i", false, "the rate-dependent friction mu(I) of dense granular flow", kMuIKeys,
     "docs/user-guide.md", "### `mu_i`"},
}};

} // namespace

std::span<const io::KeyTable> material_key_tables() {
    return kTables;
}

} // namespace grainload::materials
