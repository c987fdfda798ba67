#pragma once
// Case-file keys as the modules that read them declare them: name, type, default, meaning.

#include <span>
#include <string_view>

namespace grainload::io {

/// One case-file key as declared by the module that reads it (MOOSE's validParams): name,
/// type as the user guide states it, default as the user would write it (empty: required),
/// and a one-line meaning. The reader takes its default from here, so a default lives in one
/// place, and the key tests (tests/support/guide_table.hpp) check the user guide's tables against
/// it.
struct KeySpec {
    std::string_view name;
    std::string_view type;
    std::string_view default_text;
    std::string_view doc;
    double value = 0.0; ///< the default as a number (SI), for keys whose default is one
};

/// The spec of `name` in `specs`; nullptr when there is none.
const KeySpec* find_key_spec(std::span<const KeySpec> specs, std::string_view name);
/// The numeric default of `name` (KeySpec::value); throws std::logic_error for an undeclared key.
double default_value(std::span<const KeySpec> specs, std::string_view name);

} // namespace grainload::io
