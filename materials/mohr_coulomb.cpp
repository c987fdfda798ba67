#include "materials/mohr_coulomb.hpp"

#include "materials/cone_fit.hpp"
#include "materials/principal_stress.hpp"
#include "materials/voigt_algebra.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace grainload::materials {

namespace {
constexpr int kPlasticStrain = 0;
constexpr int kPlasticVolumetric = 1;
} // namespace

MohrCoulomb::MohrCoulomb(ElasticConstants elastic, Parameters parameters)
    : Material(elastic), parameters_(parameters) {
    const Parameters& p = parameters_;
    if (!(p.friction_angle > 0.0 && p.friction_angle < std::numbers::pi / 2.0) ||
        !(p.cohesion >= 0.0) ||
        !(p.dilatancy_angle >= 0.0 && p.dilatancy_angle <= p.friction_angle)) {
        throw std::invalid_argument("MohrCoulomb: need 0 < phi < 90 deg, c >= 0, 0 <= psi <= phi");
    }
    surface_ = {std::sin(p.friction_angle), std::cos(p.friction_angle), std::sin(p.dilatancy_angle),
                p.cohesion};
    const ConeConstants inner =
        fit_cone(ConeFit::inner, p.friction_angle, p.cohesion, p.dilatancy_angle);
    inscribed_ = {inner.alpha, inner.k, inner.alpha_flow};
}

std::vector<std::string> MohrCoulomb::state_names() const {
    return {"equivalent_plastic_strain", "plastic_volumetric_strain"};
}

double MohrCoulomb::equivalent_plastic_strain(std::span<const double> state) const {
    return state[kPlasticStrain];
}

double MohrCoulomb::yield_function(const Voigt6& stress) const {
    return surface_.yield(principal_stresses(stress).values);
}

PlasticRegion MohrCoulomb::update(const Voigt6& strain_increment, Voigt6& stress,
                                  std::span<double> state, Matrix6* tangent) const {
    const DruckerPragerTrial trial = drucker_prager_trial(elastic_, stress, strain_increment);
    const auto elastic_step = [&] {
        stress = trial.stress;
        if (tangent != nullptr) {
            *tangent = elastic_.stiffness();
        }
        return PlasticRegion::elastic;
    };
    if (trial.sqrt_j2 + inscribed_.alpha * trial.i1 - inscribed_.k <= 0.0) {
        return elastic_step();
    }
    const PrincipalStresses principal = principal_stresses(trial.stress);
    const PrincipalReturn r = mohr_coulomb_principal_return(elastic_, surface_, principal.values);
    if (r.region == PlasticRegion::elastic) {
        return elastic_step();
    }
    stress = from_principal(r.stress, principal.directions);
    // The plastic strain is the elastic strain the return removed, D^-1 (s_tr - s), coaxial.
    const Vec3 removed = principal.values - r.stress;
    const double volumetric = removed.sum() / (3.0 * elastic_.bulk_modulus);
    const Vec3 deviatoric =
        (removed - Vec3::Constant(removed.sum() / 3.0)) / (2.0 * elastic_.shear_modulus);
    state[kPlasticStrain] += std::sqrt(2.0 / 3.0) * deviatoric.norm();
    state[kPlasticVolumetric] += volumetric;
    if (tangent != nullptr) {
        *tangent = isotropic_function_derivative(r.jacobian, r.stress, principal.values,
                                                 principal.directions) *
                   elastic_.stiffness();
    }
    return r.region;
}

} // namespace grainload::materials
