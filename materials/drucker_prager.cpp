#include "materials/drucker_prager.hpp"

#include "materials/cone_fit.hpp"
#include "materials/voigt_algebra.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace grainload::materials {

namespace {
constexpr int kPlasticStrain = 0;

} // namespace

DruckerPrager::DruckerPrager(ElasticConstants elastic, Parameters parameters)
    : Material(elastic), parameters_(parameters) {
    Parameters& p = parameters_;
    if (!(p.alpha >= 0.0) || !(p.k >= 0.0) || !(p.alpha_flow >= 0.0) ||
        (p.alpha == 0.0 && p.k == 0.0)) {
        throw std::invalid_argument("DruckerPrager: need alpha, k, alpha_flow >= 0, not all 0");
    }
    if (p.alpha > 0.0) {
        p.tension_cutoff = std::min(p.tension_cutoff, p.k / p.alpha);
    }
}

std::vector<std::string> DruckerPrager::state_names() const {
    return {"equivalent_plastic_strain", "plastic_volumetric_strain"};
}

double DruckerPrager::equivalent_plastic_strain(std::span<const double> state) const {
    return state[kPlasticStrain];
}

double DruckerPrager::yield_function(const Voigt6& stress) const {
    const double sqrt_j2 = voigt::norm(voigt::deviator(stress)) / std::sqrt(2.0);
    return sqrt_j2 + parameters_.alpha * voigt::trace(stress) - parameters_.k;
}

PlasticRegion DruckerPrager::update(const Voigt6& strain_increment, Voigt6& stress,
                                    std::span<double> state, Matrix6* tangent) const {
    return drucker_prager_return(elastic_, parameters_,
                                 drucker_prager_trial(elastic_, stress, strain_increment), stress,
                                 state, tangent);
}

} // namespace grainload::materials
