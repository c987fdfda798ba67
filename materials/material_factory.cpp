#include "materials/material_factory.hpp"

#include "io/case_table.hpp"
#include "materials/drucker_prager.hpp"
#include "materials/generalized_cap.hpp"
#include "materials/linear_elastic.hpp"
#include "materials/lsdyna_material.hpp"
#include "materials/mohr_coulomb.hpp"
#include "materials/mu_i_material.hpp"
#include "materials/von_mises.hpp"

#include <array>

namespace grainload::materials {

namespace {

constexpr std::array<std::string_view, 6> kModels{"linear_elastic",  "von_mises", "drucker_prager",
                                                  "generalized_cap", "mu_i",      "mohr_coulomb"};

std::unique_ptr<Material> build(const io::CaseTable& table, std::string_view model) {
    if (model == "linear_elastic") {
        return LinearElastic::from_case(table);
    }
    if (model == "von_mises") {
        return VonMises::from_case(table);
    }
    if (model == "drucker_prager") {
        return DruckerPrager::from_case(table);
    }
    if (model == "mu_i") {
        return MuIMaterial::from_case(table);
    }
    if (model == "mohr_coulomb") {
        return MohrCoulomb::from_case(table);
    }
    return GeneralizedCap::from_case(table);
}

} // namespace

std::unique_ptr<Material> make_material(const io::CaseTable& table) {
    if (table.has("from_lsdyna")) {
        return material_from_lsdyna(table);
    }
    const std::string model = table.choice(
        "model", {kModels[0], kModels[1], kModels[2], kModels[3], kModels[4], kModels[5]});
    // The other models' sub-tables are built too, and dropped: a mistake in the keys of a
    // model the case can be switched to is reported now, not when it is switched.
    for (const std::string_view other : kModels) {
        if (other != model && table.has(other)) {
            (void)build(table.with_sub_table(other), other);
        }
    }
    return build(table.with_sub_table(model), model);
}

} // namespace grainload::materials
