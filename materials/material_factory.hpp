#pragma once
// The material of one [[material]] table, built by its model or from an LS-DYNA deck.

#include "materials/material.hpp"

#include <memory>

namespace grainload::materials {

/// Build the material described by one [[material]] table; its `model` key picks the class, or
/// its `from_lsdyna` table names a deck's MAT_025 card (materials/lsdyna_material.hpp).
std::unique_ptr<Material> make_material(const io::CaseTable& table);

} // namespace grainload::materials
