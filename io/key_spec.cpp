#include "io/key_spec.hpp"

namespace grainload::io {

const KeySpec* find_key_spec(std::span<const KeySpec> specs, std::string_view name) {
    for (const KeySpec& spec : specs) {
        if (spec.name == name) {
            return &spec;
        }
    }
    return nullptr;
}

} // namespace grainload::io
