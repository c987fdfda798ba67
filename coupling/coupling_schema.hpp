#pragma once
// The case-file tables coupling/ reads: [coupling] and the shells' faces the sand meets.

#include "io/key_spec.hpp"

#include <span>

namespace grainload::coupling {

/// [coupling], [[coupling.interface]] and [[coupling.friction]].
std::span<const io::KeyTable> coupling_key_tables();

} // namespace grainload::coupling
