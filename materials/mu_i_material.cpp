#include "materials/mu_i_material.hpp"

#include "io/case_table.hpp"

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

/// A friction coefficient given as a number (`number_key`) or as the angle whose tangent it is
/// (`angle_key`), exactly one of the two.
double read_friction(const io::CaseTable& table, std::string_view number_key,
                     std::string_view angle_key) {
    const bool by_number = table.has(number_key);
    if (by_number == table.has(angle_key)) {
        table.fail(by_number ? angle_key : number_key,
                   "give either " + std::string(number_key) + " (a number) or " +
                       std::string(angle_key) + " (an angle, mu = tan), exactly one");
    }
    if (by_number) {
        return table.number(number_key);
    }
    const double angle = table.quantity(angle_key, io::dimension::kAngle);
    if (!(angle > 0.0 && angle < std::numbers::pi / 2.0)) {
        table.fail(angle_key, "expected an angle in (0, 90) deg");
    }
    return std::tan(angle);
}

/// The law's constants, checked in the order a user reads them.
MuILaw read_law(const io::CaseTable& table, double bulk_density) {
    namespace dim = io::dimension;
    MuILaw law;
    law.mu_s = read_friction(table, "mu_s", "angle_s");
    if (!(law.mu_s > 0.0)) {
        table.fail(table.has("mu_s") ? "mu_s" : "angle_s", "expected a static friction > 0");
    }
    law.mu_2 = read_friction(table, "mu_2", "angle_2");
    // sqrt(J2) = sqrt3 p is the compression meridian of phi = 90 deg: no steeper cone exists.
    if (!(law.mu_2 >= law.mu_s && law.mu_2 < std::sqrt(3.0))) {
        table.fail(table.has("mu_2") ? "mu_2" : "angle_2",
                   "expected a limit friction between the static one (" + std::to_string(law.mu_s) +
                       ") and sqrt(3)");
    }
    law.i0 = table.number("i0");
    if (!(law.i0 > 0.0) || !std::isfinite(law.i0)) {
        table.fail("i0", "expected I0 > 0");
    }
    law.grain_diameter = table.positive_quantity("grain_size", dim::kLength);
    law.grain_density = table.positive_quantity("grain_density", dim::kDensity);
    if (law.grain_density < bulk_density) {
        table.fail("grain_density", "expected the density of the grains' solid, at least the "
                                    "bulk density " +
                                        std::to_string(bulk_density) + " kg/m^3");
    }
    return law;
}

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

std::unique_ptr<MuIMaterial> MuIMaterial::from_case(const io::CaseTable& table) {
    const ElasticConstants elastic = ElasticConstants::from_case(table);
    double amplitude = 0.0;
    if (table.has("nonlocal_amplitude")) {
        amplitude = table.number("nonlocal_amplitude");
        if (!(amplitude > 0.0) || !std::isfinite(amplitude)) {
            table.fail("nonlocal_amplitude", "expected a non-local amplitude A > 0");
        }
    }
    return std::make_unique<MuIMaterial>(elastic, read_law(table, elastic.density), amplitude);
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
