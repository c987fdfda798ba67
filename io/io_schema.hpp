#pragma once
// The case-file tables io/ reads itself: [case] and [[case.reference]].

#include "io/key_spec.hpp"

#include <span>

namespace grainload::io {

/// [case] (io/scene_settings.hpp) and [[case.reference]] (io/figure_reference.hpp).
std::span<const KeyTable> io_key_tables();

} // namespace grainload::io
