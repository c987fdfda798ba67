#include "materials/material_library.hpp"

#include "io/case_table.hpp"
#include "io/named_index.hpp"
#include "materials/material_factory.hpp"

#include <algorithm>

namespace grainload::materials {

MaterialLibrary MaterialLibrary::from_case(const io::CaseTable& root) {
    MaterialLibrary library;
    for (const auto& table : root.array_of_tables("material")) {
        std::string name = table.string("name");
        io::refuse_repeated_name(table, library.names_, name, "material");
        library.materials_.push_back(make_material(table));
        library.names_.push_back(std::move(name));
        // Read through the model's sub-table, where mu_i may hold its grain size too: one d for
        // the rheology and for Beverloo's k d.
        const io::CaseTable keys = table.with_sub_table(library.materials_.back()->model());
        library.grain_sizes_.push_back(
            keys.has("grain_size")
                ? std::optional(keys.positive_quantity("grain_size", io::dimension::kLength))
                : std::nullopt);
    }
    return library;
}

int MaterialLibrary::index_of(const io::CaseTable& table, std::string_view key) const {
    const std::string name = table.string(key);
    const auto found = std::find(names_.begin(), names_.end(), name);
    if (found == names_.end()) {
        std::string known;
        for (const auto& n : names_) {
            known += (known.empty() ? "\"" : ", \"") + n + "\"";
        }
        table.fail(key, "no [[material]] is called \"" + name +
                            "\" (defined: " + (known.empty() ? std::string("none") : known) + ")");
    }
    return static_cast<int>(found - names_.begin());
}

} // namespace grainload::materials
