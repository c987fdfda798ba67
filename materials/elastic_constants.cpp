#include "materials/elastic_constants.hpp"

#include <cmath>

namespace grainload::materials {

ElasticConstants ElasticConstants::from_young(double density, double young, double poisson) {
    return {density, young / (3.0 * (1.0 - 2.0 * poisson)), young / (2.0 * (1.0 + poisson))};
}

ElasticConstants ElasticConstants::from_bulk_shear(double density, double bulk, double shear) {
    return {density, bulk, shear};
}

ElasticConstants ElasticConstants::scaled(double s) const {
    ElasticConstants out = *this;
    out.bulk_modulus *= s;
    out.shear_modulus *= s;
    out.stiffness_scale *= s;
    return out;
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
