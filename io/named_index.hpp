#pragma once
// The index of the item a case key names, among items that each have a name.

#include "io/case_table.hpp"

#include <string>

namespace grainload::io {

/// Index into `items` of the one whose `name_of` is the string `table.key` holds; an unknown
/// name fails at that key listing the known names (`what` names their kind: "[[sph.body]]").
template <typename Named, typename NameOf>
int index_by_name(const CaseTable& table, const std::string& key, const Named& items,
                  NameOf name_of, const char* what) {
    const std::string name = table.string(key);
    std::string known;
    for (std::size_t k = 0; k < items.size(); ++k) {
        if (name_of(items[k]) == name) {
            return static_cast<int>(k);
        }
        known += (known.empty() ? "\"" : ", \"") + name_of(items[k]) + "\"";
    }
    table.fail(key, std::string("expected the name of a ") + what + " (" +
                        (known.empty() ? std::string("none defined") : known) + ")");
}

} // namespace grainload::io
