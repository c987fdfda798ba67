#pragma once
// The case-file tables materials/ reads: [[material]] and the keys of each model.

#include "io/key_spec.hpp"

#include <span>

namespace grainload::materials {

/// [[material]] and one table per model ([material.MODEL], whose keys may also stand in
/// [[material]] itself).
std::span<const io::KeyTable> material_key_tables();

} // namespace grainload::materials
