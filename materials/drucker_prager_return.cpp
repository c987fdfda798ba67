#include "materials/drucker_prager_return.hpp"

#include "materials/voigt_algebra.hpp"

#include <cmath>

namespace grainload::materials {

namespace {

constexpr int kPlasticStrain = 0;
constexpr int kPlasticVolumetric = 1;

// Cone: sigma = sigma_tr - dg D_e dg/dsigma with dg/dsigma = n / sqrt2 + alpha_flow 1, so sqrt(J2)
// drops by G dg and I1 by 9 K alpha_flow dg; f = 0 gives dg = f_tr / (G + 9K alpha alpha_flow).
// Tangent (de Souza Neto eq. 8.74 without hardening):
// D = D_e - a (x) b / (G + 9K alpha alpha_flow) - (G dg / sqrt(J2_tr)) (2G I_dev - 2G n (x) n),
// a = sqrt2 G n + 3K alpha_flow 1 (flow), b = sqrt2 G n + 3K alpha 1 (yield normal).
void return_to_cone(const ElasticConstants& elastic, const DruckerPragerCone& p,
                    const DruckerPragerTrial& trial, double multiplier, Voigt6& stress,
                    Matrix6* tangent) {
    const double bulk = elastic.bulk_modulus;
    const double shear = elastic.shear_modulus;
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
    *tangent = elastic.stiffness() -
               voigt::outer(flow, normal) / (shear + 9.0 * bulk * p.alpha * p.alpha_flow) -
               ratio * (voigt::deviatoric_stiffness(shear) - 2.0 * shear * voigt::outer(n, n));
}

// Cutoff plane I1 = T with associated flow (direction 1): the deviator is untouched, so
// D = 2G I_dev.
void return_to_cutoff(const ElasticConstants& elastic, const DruckerPragerCone& p,
                      const DruckerPragerTrial& trial, Voigt6& stress, Matrix6* tangent) {
    stress = trial.deviator + (p.tension_cutoff / 3.0) * voigt::identity();
    if (tangent != nullptr) {
        *tangent = voigt::deviatoric_stiffness(elastic.shear_modulus);
    }
}

// Corner circle I1 = T, sqrt(J2) = k - alpha T (the apex point when T = k / alpha): both
// multipliers active; the stress keeps the trial Lode direction n, so
// s = sqrt2 (k - alpha T) n and D = ((k - alpha T) / sqrt(J2_tr)) (2G I_dev - 2G n (x) n).
void return_to_corner(const ElasticConstants& elastic, const DruckerPragerCone& p,
                      const DruckerPragerTrial& trial, Voigt6& stress, Matrix6* tangent) {
    const double shear = elastic.shear_modulus;
    const double ratio = (p.k - p.alpha * p.tension_cutoff) / trial.sqrt_j2;
    stress = ratio * trial.deviator + (p.tension_cutoff / 3.0) * voigt::identity();
    if (tangent == nullptr) {
        return;
    }
    const Voigt6 n = trial.deviator / (std::sqrt(2.0) * trial.sqrt_j2);
    *tangent = ratio * (voigt::deviatoric_stiffness(shear) - 2.0 * shear * voigt::outer(n, n));
}

} // namespace

DruckerPragerTrial drucker_prager_trial(const ElasticConstants& elastic, const Voigt6& stress,
                                        const Voigt6& strain_increment) {
    DruckerPragerTrial trial;
    trial.stress = stress + elastic.stress_from_strain(strain_increment);
    trial.deviator = voigt::deviator(trial.stress);
    trial.i1 = voigt::trace(trial.stress);
    trial.sqrt_j2 = voigt::norm(trial.deviator) / std::sqrt(2.0);
    return trial;
}

PlasticRegion drucker_prager_return(const ElasticConstants& elastic, const DruckerPragerCone& p,
                                    const DruckerPragerTrial& trial, Voigt6& stress,
                                    std::span<double> state, Matrix6* tangent) {
    const double bulk = elastic.bulk_modulus;
    const double shear = elastic.shear_modulus;
    const double f_cone = trial.sqrt_j2 + p.alpha * trial.i1 - p.k;
    if (f_cone <= 0.0 && trial.i1 <= p.tension_cutoff) {
        stress = trial.stress;
        if (tangent != nullptr) {
            *tangent = elastic.stiffness();
        }
        return PlasticRegion::elastic;
    }
    PlasticRegion region = PlasticRegion::apex;
    // Cone return first: valid when it lands on the cone below the cutoff (I1 <= T).
    const double multiplier = f_cone / (shear + 9.0 * bulk * p.alpha * p.alpha_flow);
    if (f_cone > 0.0 && trial.i1 - 9.0 * bulk * p.alpha_flow * multiplier <= p.tension_cutoff) {
        return_to_cone(elastic, p, trial, multiplier, stress, tangent);
        region = PlasticRegion::failure_surface;
    } else if (trial.sqrt_j2 <= p.k - p.alpha * p.tension_cutoff) {
        return_to_cutoff(elastic, p, trial, stress, tangent);
    } else {
        return_to_corner(elastic, p, trial, stress, tangent);
    }
    // Plastic strains from the stress correction: d(eps_v^p) = dI1 / 3K, de^p = ds / 2G.
    state[kPlasticVolumetric] += (trial.i1 - voigt::trace(stress)) / (3.0 * bulk);
    state[kPlasticStrain] += std::sqrt(2.0 / 3.0) *
                             voigt::norm(trial.deviator - voigt::deviator(stress)) / (2.0 * shear);
    return region;
}

} // namespace grainload::materials
