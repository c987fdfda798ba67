#pragma once
// The index of the item a case key names, among items that each have a name, and the refusal
// of a name given twice.

#include "io/case_table.hpp"

#include <algorithm>
#include <functional>
#include <string>
#include <string_view>

namespace grainload::io {

/// The names of `items` (read through `name_of`, as in refuse_repeated_name) as a message lists
/// them: "sand", "steel"; empty when there are none.
template <typename Named, typename NameOf = std::identity>
std::string quoted_names(const Named& items, NameOf name_of = {}) {
    std::string list;
    for (const auto& item : items) {
        list += (list.empty() ? "\"" : ", \"") + std::string(std::invoke(name_of, item)) + "\"";
    }
    return list;
}

/// Index into `items` of the one whose `name_of` is the string `table.key` holds; an unknown
/// name fails at that key listing the known names (`what` names their kind: "[[sph.body]]").
template <typename Named, typename NameOf>
int index_by_name(const CaseTable& table, const std::string& key, const Named& items,
                  NameOf name_of, const char* what) {
    const std::string name = table.string(key);
    for (std::size_t k = 0; k < items.size(); ++k) {
        if (name_of(items[k]) == name) {
            return static_cast<int>(k);
        }
    }
    const std::string known = quoted_names(items, name_of);
    table.fail(key, std::string("expected the name of a ") + what + " (" +
                        (known.empty() ? std::string("none defined") : known) + ")");
}

/// Refuses `table`, at its `name` key, when `name` is already the name of one of `known` (read
/// through `name_of`: a member pointer such as `&Sink::name`, or nothing for a list of names):
/// "a sink called "below" is already defined". Every reader of named tables ([[material]],
/// bodies, shells, sinks, sources, phases, wall maps, DEM bodies and walls) refuses this way.
template <typename Known, typename NameOf = std::identity>
void refuse_repeated_name(const CaseTable& table, const Known& known, const std::string& name,
                          std::string_view what, NameOf name_of = {}) {
    if (std::ranges::any_of(
            known, [&](const auto& other) { return std::invoke(name_of, other) == name; })) {
        table.fail("name",
                   "a " + std::string(what) + " called \"" + name + "\" is already defined");
    }
}

} // namespace grainload::io
