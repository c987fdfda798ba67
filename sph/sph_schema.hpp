#pragma once
// The case-file tables sph/ reads: the particles, their walls and every scene part around them.

#include "io/key_spec.hpp"

#include <span>

namespace grainload::sph {

/// Every table the SPH readers take keys from, each declared next to its reader.
std::span<const io::KeyTable> sph_key_tables();

} // namespace grainload::sph
