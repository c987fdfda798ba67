#pragma once
// The case-file tables fem/ reads: [fem], its shell parts and everything on them.

#include "io/key_spec.hpp"

#include <span>

namespace grainload::fem {

/// Every table the shell readers take keys from, each declared next to its reader: [fem],
/// [[fem.shell]] (one part per mesh source the user guide documents), its boundaries, loads,
/// monitors, reactions and Gmsh groups, and [[fem.time_function]].
std::span<const io::KeyTable> fem_key_tables();

} // namespace grainload::fem
