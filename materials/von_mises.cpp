#include "materials/von_mises.hpp"

#include "materials/voigt_algebra.hpp"

#include <cmath>
#include <stdexcept>

namespace grainload::materials {

namespace {
constexpr int kBackStress = 0;
constexpr int kPlasticStrain = 6;
} // namespace

VonMises::VonMises(ElasticConstants elastic, double yield_stress, double tangent_modulus,
                   double beta)
    : Material(elastic), yield_stress_(yield_stress), beta_(beta) {
    const double young = elastic.young();
    if (!(yield_stress > 0.0) || !(tangent_modulus >= 0.0 && tangent_modulus < young) ||
        !(beta >= 0.0 && beta <= 1.0)) {
        throw std::invalid_argument(
            "VonMises: need yield_stress > 0, 0 <= E_T < E, 0 <= beta <= 1");
    }
    // Thesis 4.6.2.1: slope of stress against plastic strain in a uniaxial test.
    plastic_modulus_ = young * tangent_modulus / (young - tangent_modulus);
}

std::vector<std::string> VonMises::state_names() const {
    return {"back_stress_xx", "back_stress_yy", "back_stress_zz",           "back_stress_xy",
            "back_stress_yz", "back_stress_zx", "equivalent_plastic_strain"};
}

double VonMises::equivalent_plastic_strain(std::span<const double> state) const {
    return state[kPlasticStrain];
}

double VonMises::current_yield_stress(std::span<const double> state) const {
    return yield_stress_ + beta_ * plastic_modulus_ * state[kPlasticStrain];
}

PlasticRegion VonMises::update(const Voigt6& strain_increment, Voigt6& stress,
                               std::span<double> state, Matrix6* tangent) const {
    const double shear = elastic_.shear_modulus;
    const Matrix6 elastic_stiffness = elastic_.stiffness();
    const Voigt6 trial = stress + elastic_stiffness * strain_increment;
    Eigen::Map<Voigt6> back_stress(state.data() + kBackStress);
    // Relative trial deviator eta (4.6.2.13) and trial equivalent stress (4.6.2.16).
    const Voigt6 eta = voigt::deviator(trial) - back_stress;
    const double eta_norm = voigt::norm(eta);
    const double trial_equivalent = std::sqrt(1.5) * eta_norm;
    const double f_trial = trial_equivalent - current_yield_stress(state);
    if (f_trial <= 0.0) {
        stress = trial;
        if (tangent != nullptr) {
            *tangent = elastic_stiffness;
        }
        return PlasticRegion::elastic;
    }
    // 4.6.2.28 with the mixed-hardening modulus: isotropic beta E_p grows the radius, kinematic
    // (1 - beta) E_p moves the centre towards the trial point; both shrink f by E_p per unit
    // multiplier, so the scalar equation is linear and the return exact.
    const double multiplier = f_trial / (3.0 * shear + plastic_modulus_);
    const double scale = multiplier / trial_equivalent;
    stress = trial - 3.0 * shear * scale * eta;                    // 4.6.2.29
    back_stress += (1.0 - beta_) * plastic_modulus_ * scale * eta; // 4.6.2.30
    state[kPlasticStrain] += multiplier;                           // 4.6.2.20
    if (tangent != nullptr) {
        *tangent = plastic_tangent(eta / eta_norm, trial_equivalent, multiplier);
    }
    return PlasticRegion::failure_surface;
}

// Consistent tangent of the radial return (de Souza Neto, Peric & Owen, "Computational Methods
// for Plasticity", eq. 7.120, with H replaced by the mixed-hardening E_p):
// D = D_e - (3 G dl / q) 2G I_dev + 6 G^2 (dl / q - 1 / (3G + E_p)) n (x) n.
Matrix6 VonMises::plastic_tangent(const Voigt6& unit_normal, double trial_equivalent,
                                  double multiplier) const {
    const double shear = elastic_.shear_modulus;
    const double ratio = 3.0 * shear * multiplier / trial_equivalent;
    const double normal_coefficient =
        6.0 * shear * shear *
        (multiplier / trial_equivalent - 1.0 / (3.0 * shear + plastic_modulus_));
    return elastic_.stiffness() - ratio * voigt::deviatoric_stiffness(shear) +
           normal_coefficient * voigt::outer(unit_normal, unit_normal);
}

} // namespace grainload::materials
