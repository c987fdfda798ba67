#include "materials/elastic_constants.hpp"

#include "io/case_table.hpp"
#include "materials/material_keys.hpp"

#include <cmath>

namespace grainload::materials {

ElasticConstants ElasticConstants::from_young(double density, double young, double poisson) {
    return {density, young / (3.0 * (1.0 - 2.0 * poisson)), young / (2.0 * (1.0 + poisson))};
}

ElasticConstants ElasticConstants::from_bulk_shear(double density, double bulk, double shear) {
    return {density, bulk, shear};
}

double ElasticConstants::read_stiffness_scale(const io::CaseTable& table) {
    const double s =
        table.number_or("stiffness_scale", io::default_value(kMaterialKeys, "stiffness_scale"));
    if (!(s > 0.0) || !std::isfinite(s)) {
        table.fail("stiffness_scale", "expected a factor > 0 on the bulk and shear moduli");
    }
    return s;
}

ElasticConstants ElasticConstants::scaled(double s) const {
    ElasticConstants out = *this;
    out.bulk_modulus *= s;
    out.shear_modulus *= s;
    out.stiffness_scale *= s;
    return out;
}

namespace {

/// Density and the elastic pair as the table gives them, before stiffness_scale.
ElasticConstants read_moduli(const io::CaseTable& table) {
    namespace dim = io::dimension;
    const double density = table.positive_quantity("density", dim::kDensity);
    const bool by_young = table.has("youngs_modulus") || table.has("poisson_ratio");
    const bool by_moduli = table.has("bulk_modulus") || table.has("shear_modulus");
    if (by_young == by_moduli) {
        table.fail("", "expected either youngs_modulus and poisson_ratio, or bulk_modulus and "
                       "shear_modulus (exactly one pair)");
    }
    if (by_young) {
        const double young = table.positive_quantity("youngs_modulus", dim::kPressure);
        const double poisson = table.number("poisson_ratio");
        if (!(poisson > -1.0 && poisson < 0.5)) {
            table.fail("poisson_ratio", "expected a Poisson ratio in (-1, 0.5)");
        }
        return ElasticConstants::from_young(density, young, poisson);
    }
    return ElasticConstants::from_bulk_shear(
        density, table.positive_quantity("bulk_modulus", dim::kPressure),
        table.positive_quantity("shear_modulus", dim::kPressure));
}

} // namespace

ElasticConstants ElasticConstants::from_case(const io::CaseTable& table) {
    return read_moduli(table).scaled(read_stiffness_scale(table));
}

double ElasticConstants::young() const {
    return 9.0 * bulk_modulus * shear_modulus / (3.0 * bulk_modulus + shear_modulus);
}

double ElasticConstants::poisson() const {
    return (3.0 * bulk_modulus - 2.0 * shear_modulus) /
           (2.0 * (3.0 * bulk_modulus + shear_modulus));
}

double ElasticConstants::p_wave_speed() const {
    return std::sqrt((bulk_modulus + 4.0 * shear_modulus / 3.0) / density);
}

double ElasticConstants::unscaled_p_wave_speed() const {
    return p_wave_speed() / std::sqrt(stiffness_scale);
}

Matrix6 ElasticConstants::stiffness() const {
    Matrix6 d = Matrix6::Zero();
    const double lambda = lame_lambda();
    d.topLeftCorner<3, 3>().setConstant(lambda);
    for (int i = 0; i < 3; ++i) {
        d(i, i) += 2.0 * shear_modulus;
        d(i + 3, i + 3) = shear_modulus;
    }
    return d;
}

} // namespace grainload::materials
