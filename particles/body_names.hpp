#pragma once
// The bodies of a particle scene by name, as a scene part's `body` key names them.

#include "io/named_index.hpp"

#include <string>
#include <vector>

namespace grainload::particles {

/// The bodies of a particle method's scene, indexed by body id, and the case table that
/// declares them ("[[sph.body]]"), which an unknown name's message cites.
struct BodyNames {
    std::string declared_in;
    std::vector<std::string> names;

    /// Index of the body that `table.key` names; an unknown name fails there, listing the known.
    int index(const io::CaseTable& table, const std::string& key) const {
        return io::index_by_name(
            table, key, names, [](const std::string& s) { return s; }, declared_in.c_str());
    }
};

} // namespace grainload::particles
