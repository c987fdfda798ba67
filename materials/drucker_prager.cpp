#include "materials/drucker_prager.hpp"

#include "io/case_table.hpp"
#include "materials/cone_fit.hpp"
#include "materials/voigt_algebra.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace grainload::materials {

namespace {
constexpr int kPlasticStrain = 0;

DruckerPrager::Parameters parameters_from_angles(const io::CaseTable& table) {
    namespace dim = io::dimension;
    const double phi = table.quantity("friction_angle", dim::kAngle);
    const double cohesion = table.positive_quantity("cohesion", dim::kPressure, true);
    const double psi = table.quantity("dilatancy_angle", dim::kAngle);
    if (!(phi >= 0.0 && phi < std::acos(-1.0) / 2.0)) {
        table.fail("friction_angle", "expected an angle in [0, 90) deg");
    }
    if (!(psi >= 0.0 && psi <= phi)) {
        table.fail("dilatancy_angle", "expected an angle between 0 and the friction angle");
    }
    const ConeFit fit = cone_fit_from_name(
        table.choice("cone_fit", {"plane_strain", "compression", "extension", "inner"}));
    const ConeConstants cone = fit_cone(fit, phi, cohesion, psi);
    return {cone.alpha, cone.k, cone.alpha_flow};
}

DruckerPrager::Parameters parameters_from_thesis(const io::CaseTable& table) {
    namespace dim = io::dimension;
    if (table.has("friction_angle") || table.has("cohesion") || table.has("cone_fit")) {
        table.fail("dp_k", "give either (dp_k, dp_theta) or (friction_angle, cohesion, "
                           "dilatancy_angle, cone_fit), not both");
    }
    const double k = table.positive_quantity("dp_k", dim::kPressure, true);
    const double theta = table.number("dp_theta");
    if (!(theta >= 0.0)) {
        table.fail("dp_theta", "expected dp_theta >= 0");
    }
    const double theta_flow = table.number_or("dp_theta_flow", theta);
    if (!(theta_flow >= 0.0 && theta_flow <= theta)) {
        table.fail("dp_theta_flow", "expected a number between 0 and dp_theta");
    }
    return {theta, k, theta_flow};
}
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

std::unique_ptr<DruckerPrager> DruckerPrager::from_case(const io::CaseTable& table) {
    const ElasticConstants elastic = ElasticConstants::from_case(table);
    Parameters parameters = table.has("dp_k") || table.has("dp_theta")
                                ? parameters_from_thesis(table)
                                : parameters_from_angles(table);
    if (table.has("tension_cutoff")) {
        const double cutoff = table.quantity("tension_cutoff", io::dimension::kPressure);
        if (parameters.alpha > 0.0 && cutoff > parameters.k / parameters.alpha) {
            table.fail("tension_cutoff", "the cutoff on I1 lies beyond the cone apex k/alpha");
        }
        parameters.tension_cutoff = cutoff;
    }
    if (parameters.alpha == 0.0 && parameters.k == 0.0) {
        table.fail("", "a Drucker-Prager material with zero friction and zero cohesion has no "
                       "strength");
    }
    return std::make_unique<DruckerPrager>(elastic, parameters);
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
