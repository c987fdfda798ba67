#include "materials/material_factory.hpp"

#include "io/case_table.hpp"
#include "materials/drucker_prager.hpp"
#include "materials/generalized_cap.hpp"
#include "materials/linear_elastic.hpp"
#include "materials/lsdyna_material.hpp"
#include "materials/von_mises.hpp"

namespace grainload::materials {

std::unique_ptr<Material> make_material(const io::CaseTable& table) {
    if (table.has("from_lsdyna")) {
        return material_from_lsdyna(table);
    }
    const std::string model =
        table.choice("model", {"linear_elastic", "von_mises", "drucker_prager", "generalized_cap"});
    if (model == "linear_elastic") {
        return LinearElastic::from_case(table);
    }
    if (model == "von_mises") {
        return VonMises::from_case(table);
    }
    if (model == "drucker_prager") {
        return DruckerPrager::from_case(table);
    }
    if (model == "generalized_cap") {
        return GeneralizedCap::from_case(table);
    }
    table.fail("model", "unknown material model");
}

} // namespace grainload::materials
