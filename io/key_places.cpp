#include "io/key_places.hpp"

#include "io/case_error.hpp"
#include "io/case_table.hpp"

#include <stdexcept>

namespace grainload::io {

KeyPlaces::KeyPlaces(const CaseTable& table, std::initializer_list<std::string_view> keys) {
    for (const std::string_view key : keys) {
        places_.push_back({std::string(key), table.where(key), table.has(key)});
    }
}

const KeyPlaces::Place& KeyPlaces::place(std::string_view key) const {
    for (const Place& p : places_) {
        if (p.key == key) {
            return p;
        }
    }
    throw std::logic_error("KeyPlaces: key '" + std::string(key) + "' was not taken");
}

bool KeyPlaces::has(std::string_view key) const {
    return place(key).held;
}

const std::string& KeyPlaces::where(std::string_view key) const {
    return place(key).where;
}

void KeyPlaces::fail(std::string_view key, std::string_view message) const {
    throw CaseError(where(key) + ": " + std::string(message));
}

} // namespace grainload::io
