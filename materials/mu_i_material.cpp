#include "materials/mu_i_material.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace grainload::materials {

namespace {

constexpr int kPlasticStrain = 0;
constexpr int kInertialNumber = 2;
constexpr int kFluidity = 3;
constexpr int kExcess = 4;

} // namespace

MuIMaterial::MuIMaterial(ElasticConstants elastic, MuILaw law, double nonlocal_amplitude)
    : Material(elastic),
      law_(law), fluidity_{law, nonlocal_amplitude, kInertialNumber, kFluidity, kExcess} {
    if (!(law_.mu_s > 0.0) || !(law_.mu_2 >= law_.mu_s) || !(law_.i0 > 0.0) ||
        !(law_.grain_diameter > 0.0) || !(law_.grain_density > 0.0) ||
        !(nonlocal_amplitude >= 0.0)) {
        throw std::invalid_argument("MuIMaterial: need mu_2 >= mu_s > 0, I0, grain size, grain "
                                    "density > 0 and a non-local amplitude >= 0");
    }
}

DruckerPragerCone MuIMaterial::cone(double mu) {
    // k = 0: the apex is the origin and the cutoff sits on it (DruckerPrager's default k/alpha).
    return {mu / 3.0, 0.0, 0.0, 0.0};
}

std::vector<std::string> MuIMaterial::state_names() const {
    std::vector<std::string> names{"equivalent_plastic_strain", "plastic_volumetric_strain",
                                   "inertial_number"};
    if (nonlocal_fluidity() != nullptr) {
        names.insert(names.end(), {"fluidity", "fluidity_excess"});
    }
    return names;
}

std::vector<Material::StateField> MuIMaterial::frame_state() const {
    std::vector<StateField> fields{{"inertial_number", kInertialNumber}};
    if (nonlocal_fluidity() != nullptr) {
        fields.push_back({"fluidity", kFluidity});
    }
    return fields;
}

double MuIMaterial::equivalent_plastic_strain(std::span<const double> state) const {
    return state[kPlasticStrain];
}

PlasticRegion MuIMaterial::update(const Voigt6& strain_increment, Voigt6& stress,
                                  std::span<double> state, Matrix6* tangent) const {
    return update_over(strain_increment, std::numeric_limits<double>::infinity(), stress, state,
                       tangent);
}

PlasticRegion MuIMaterial::update_over(const Voigt6& strain_increment, double time_step,
                                       Voigt6& stress, std::span<double> state,
                                       Matrix6* tangent) const {
    const DruckerPragerTrial trial = drucker_prager_trial(elastic_, stress, strain_increment);
    if (nonlocal_fluidity() != nullptr && std::isfinite(time_step)) {
        return fluidity_return(elastic_, fluidity_, trial, time_step, stress, state, tangent);
    }
    DruckerPragerCone step_cone = cone(law_.mu_s);
    double inertial = 0.0;
    // Inside the static cone (there I1 <= 0) the step is elastic whatever the rate, as mu(I) >=
    // mu_s only widens the cone: the rate is needed only outside it, where most steps are not.
    if (trial.sqrt_j2 + step_cone.alpha * trial.i1 > 0.0) {
        // The step's shear rate and its trial pressure: the cone return keeps I1
        // (alpha_flow = 0), so p is also the pressure the step ends at.
        inertial = law_.inertial_number(shear_rate(strain_increment, time_step), -trial.i1 / 3.0);
        step_cone = cone(law_.friction(inertial));
    }
    // Where p <= 0 the grains carry no pressure and I is undefined (the law takes it as
    // infinite, mu = mu_2): the state says so with NaN, which colour maps leave out.
    state[kInertialNumber] =
        std::isfinite(inertial) ? inertial : std::numeric_limits<double>::quiet_NaN();
    return drucker_prager_return(elastic_, step_cone, trial, stress, state, tangent);
}

} // namespace grainload::materials
