#include "materials/mu_i_law.hpp"

#include "materials/voigt_algebra.hpp"

#include <cmath>
#include <limits>

namespace grainload::materials {

double MuILaw::inertial_number(double shear_rate, double pressure) const {
    if (!(shear_rate > 0.0)) {
        return 0.0;
    }
    if (!(pressure > 0.0)) {
        return std::numeric_limits<double>::infinity();
    }
    return shear_rate * grain_diameter / std::sqrt(pressure / grain_density);
}

double MuILaw::friction(double inertial_number) const {
    // Jop et al. (2006) eq. 2 written as I / (I0 + I): the same function without dividing by
    // I = 0, and mu_s + 0 = mu_s to the bit at rest.
    if (std::isinf(inertial_number)) {
        return mu_2;
    }
    return mu_s + (mu_2 - mu_s) * (inertial_number / (i0 + inertial_number));
}

double MuILaw::inertial_number_at(double mu) const {
    if (!(mu > mu_s)) {
        return 0.0;
    }
    if (!(mu < mu_2)) {
        return std::numeric_limits<double>::infinity();
    }
    return i0 * (mu - mu_s) / (mu_2 - mu);
}

double MuILaw::inertial_number_slope(double mu) const {
    const double gap = mu_2 - mu;
    return i0 * (mu_2 - mu_s) / (gap * gap);
}

double shear_rate(const Voigt6& strain_increment, double time_step) {
    // ||dev(d_eps)|| with tensor shears; sqrt(2 D':D') = sqrt2 ||D'||.
    const Voigt6 deviator = voigt::deviator(voigt::tensor_from_engineering(strain_increment));
    return std::sqrt(2.0) * voigt::norm(deviator) / time_step;
}

} // namespace grainload::materials
