#pragma once
// The case-file tables dem/ reads: the grains, their contact law and their walls.

#include "io/key_spec.hpp"

#include <span>

namespace grainload::dem {

/// Every table the DEM readers take keys from, each declared next to its reader.
std::span<const io::KeyTable> dem_key_tables();

} // namespace grainload::dem
