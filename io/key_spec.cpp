#include "io/key_spec.hpp"

#include <stdexcept>
#include <string>

namespace grainload::io {

const KeySpec* find_key_spec(std::span<const KeySpec> specs, std::string_view name) {
    for (const KeySpec& spec : specs) {
        if (spec.name == name) {
            return &spec;
        }
    }
    return nullptr;
}

double default_value(std::span<const KeySpec> specs, std::string_view name) {
    const KeySpec* spec = find_key_spec(specs, name);
    if (spec == nullptr) {
        throw std::logic_error("no declared key '" + std::string(name) + "'");
    }
    return spec->value;
}

} // namespace grainload::io
