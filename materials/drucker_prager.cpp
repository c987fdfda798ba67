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
constexpr int kPlasticVolumetric = 1;

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

/// Trial (elastic predictor) state and its invariants.
struct DruckerPrager::Trial {
    Voigt6 deviator;
    double i1 = 0.0;
    double sqrt_j2 = 0.0;
};

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
    const Parameters& p = parameters_;
    const double bulk = elastic_.bulk_modulus;
    const double shear = elastic_.shear_modulus;
    const Voigt6 trial_stress = stress + elastic_.stress_from_strain(strain_increment);
    Trial trial;
    trial.deviator = voigt::deviator(trial_stress);
    trial.i1 = voigt::trace(trial_stress);
    trial.sqrt_j2 = voigt::norm(trial.deviator) / std::sqrt(2.0);
    const double f_cone = trial.sqrt_j2 + p.alpha * trial.i1 - p.k;
    if (f_cone <= 0.0 && trial.i1 <= p.tension_cutoff) {
        stress = trial_stress;
        if (tangent != nullptr) {
            *tangent = elastic_.stiffness();
        }
        return PlasticRegion::elastic;
    }
    PlasticRegion region = PlasticRegion::apex;
    // Cone return first: valid when it lands on the cone below the cutoff (I1 <= T).
    const double multiplier = f_cone / (shear + 9.0 * bulk * p.alpha * p.alpha_flow);
    if (f_cone > 0.0 && trial.i1 - 9.0 * bulk * p.alpha_flow * multiplier <= p.tension_cutoff) {
        return_to_cone(trial, multiplier, stress, tangent);
        region = PlasticRegion::failure_surface;
    } else if (trial.sqrt_j2 <= p.k - p.alpha * p.tension_cutoff) {
        return_to_cutoff(trial, stress, tangent);
    } else {
        return_to_corner(trial, stress, tangent);
    }
    // Plastic strains from the stress correction: d(eps_v^p) = dI1 / 3K, de^p = ds / 2G.
    state[kPlasticVolumetric] += (trial.i1 - voigt::trace(stress)) / (3.0 * bulk);
    state[kPlasticStrain] += std::sqrt(2.0 / 3.0) *
                             voigt::norm(trial.deviator - voigt::deviator(stress)) / (2.0 * shear);
    return region;
}

// Cone: sigma = sigma_tr - dg D_e dg/dsigma with dg/dsigma = n / sqrt2 + alpha_flow 1, so sqrt(J2)
// drops by G dg and I1 by 9 K alpha_flow dg; f = 0 gives dg = f_tr / (G + 9 K alpha alpha_flow).
// Tangent (de Souza Neto eq. 8.74 without hardening):
// D = D_e - a (x) b / (G + 9K alpha alpha_flow) - (G dg / sqrt(J2_tr)) (2G I_dev - 2G n (x) n),
// a = sqrt2 G n + 3K alpha_flow 1 (flow), b = sqrt2 G n + 3K alpha 1 (yield normal).
void DruckerPrager::return_to_cone(const Trial& trial, double multiplier, Voigt6& stress,
                                   Matrix6* tangent) const {
    const Parameters& p = parameters_;
    const double bulk = elastic_.bulk_modulus;
    const double shear = elastic_.shear_modulus;
    const double sqrt_j2 = trial.sqrt_j2 - shear * multiplier;
    const double i1 = trial.i1 - 9.0 * bulk * p.alpha_flow * multiplier;
    stress = (sqrt_j2 / trial.sqrt_j2) * trial.deviator + (i1 / 3.0) * voigt::identity();
    if (tangent == nullptr) {
        return;
    }
    const Voigt6 n = trial.deviator / (std::sqrt(2.0) * trial.sqrt_j2);
    const Voigt6 flow = std::sqrt(2.0) * shear * n + 3.0 * bulk * p.alpha_flow * voigt::identity();
    const Voigt6 normal = std::sqrt(2.0) * shear * n + 3.0 * bulk * p.alpha * voigt::identity();
    const double ratio = shear * multiplier / trial.sqrt_j2;
    *tangent = elastic_.stiffness() -
               voigt::outer(flow, normal) / (shear + 9.0 * bulk * p.alpha * p.alpha_flow) -
               ratio * (voigt::deviatoric_stiffness(shear) - 2.0 * shear * voigt::outer(n, n));
}

// Cutoff plane I1 = T with associated flow (direction 1): the deviator is untouched, so
// D = 2G I_dev.
void DruckerPrager::return_to_cutoff(const Trial& trial, Voigt6& stress, Matrix6* tangent) const {
    stress = trial.deviator + (parameters_.tension_cutoff / 3.0) * voigt::identity();
    if (tangent != nullptr) {
        *tangent = voigt::deviatoric_stiffness(elastic_.shear_modulus);
    }
}

// Corner circle I1 = T, sqrt(J2) = k - alpha T (the apex point when T = k / alpha): both
// multipliers active; the stress keeps the trial Lode direction n, so
// s = sqrt2 (k - alpha T) n and D = ((k - alpha T) / sqrt(J2_tr)) (2G I_dev - 2G n (x) n).
void DruckerPrager::return_to_corner(const Trial& trial, Voigt6& stress, Matrix6* tangent) const {
    const Parameters& p = parameters_;
    const double shear = elastic_.shear_modulus;
    const double ratio = (p.k - p.alpha * p.tension_cutoff) / trial.sqrt_j2;
    stress = ratio * trial.deviator + (p.tension_cutoff / 3.0) * voigt::identity();
    if (tangent == nullptr) {
        return;
    }
    const Voigt6 n = trial.deviator / (std::sqrt(2.0) * trial.sqrt_j2);
    *tangent = ratio * (voigt::deviatoric_stiffness(shear) - 2.0 * shear * voigt::outer(n, n));
}

} // namespace grainload::materials
