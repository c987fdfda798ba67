#include "materials/generalized_cap.hpp"

#include "io/case_table.hpp"

#include <cmath>
#include <stdexcept>

namespace grainload::materials {
namespace {

const Voigt6 kIdentity = (Voigt6() << 1.0, 1.0, 1.0, 0.0, 0.0, 0.0).finished();

/// sqrt(J2) of a deviator in Voigt form with tensor shear components.
double root_j2(const Voigt6& s) {
    return std::sqrt(0.5 * s.head<3>().squaredNorm() + s.tail<3>().squaredNorm());
}

/// Consistent tangent from the invariant-plane Jacobian. With sigma = (I1/3) 1 + rho s_tr,
/// dI1_tr = 3K 1.deps, ds_tr = D_dev deps and dq_tr = (G/q_tr) s_tr.deps (engineering shear):
/// C = 1 (x) dI1/3 + rho D_dev + s_tr (x) drho.
Matrix6 consistent_tangent(const ElasticConstants& e, const cap::Return& r, const Voigt6& s_tr,
                           double q_tr) {
    const double k3 = 3.0 * e.bulk_modulus;
    const Matrix6 d_dev = e.stiffness() - e.bulk_modulus * kIdentity * kIdentity.transpose();
    const Voigt6 dq = q_tr > 0.0 ? Voigt6(e.shear_modulus / q_tr * s_tr) : Voigt6::Zero();
    const Voigt6 di1 = k3 * r.di1_di1 * kIdentity + r.di1_dq * dq;
    const Voigt6 drho = k3 * r.drho_di1 * kIdentity + r.drho_dq * dq;
    return kIdentity * di1.transpose() / 3.0 + r.rho * d_dev + s_tr * drho.transpose();
}

/// Increment of sqrt(2/3 deps^p : deps^p) from the trial and final invariants: the deviatoric
/// plastic strain is (1 - rho) s_tr / (2G), the volumetric one (I1_tr - I1) / (3K).
double equivalent_increment(const ElasticConstants& e, double i1_tr, double q_tr,
                            const cap::Return& r) {
    const double dev = (1.0 - r.rho) * q_tr / e.shear_modulus;
    const double vol = (i1_tr - r.i1) / (3.0 * e.bulk_modulus);
    return std::sqrt(2.0 / 3.0 * (0.5 * dev * dev + vol * vol / 3.0));
}

} // namespace

GeneralizedCap::GeneralizedCap(ElasticConstants elastic, cap::Parameters parameters)
    : Material(elastic), model_{parameters, elastic.bulk_modulus, elastic.shear_modulus, 0.0} {
    const auto [key, message] = check(parameters);
    if (!key.empty()) {
        throw std::invalid_argument("generalized_cap: " + key + ": " + message);
    }
    model_.i1_min = cap::minimum_pressure(parameters);
}

std::pair<std::string, std::string> GeneralizedCap::check(const cap::Parameters& p) {
    if (!(p.theta >= 0.0)) {
        return {"cap_theta", "expected theta >= 0"};
    }
    if (!(p.gamma >= 0.0)) {
        return {"cap_gamma", "expected gamma >= 0"};
    }
    if (!(p.beta >= 0.0)) {
        return {"cap_beta", "expected B1 >= 0"};
    }
    if (!(p.D > 0.0)) {
        return {"cap_D", "expected D > 0 (hardening rate)"};
    }
    if (!(p.W > 0.0)) {
        return {"cap_W", "expected W > 0 (maximum plastic compaction)"};
    }
    if (!(p.R >= 0.0)) {
        return {"cap_R", "expected R >= 0 (0 is a flat cap)"};
    }
    if (!(p.tension >= 0.0)) {
        return {"tension_cutoff", "expected T >= 0"};
    }
    // F(I1) must become positive for large I1, or no stress is admissible.
    const double far_strength = p.beta > 0.0 ? p.k : p.k - p.gamma;
    if (!(p.theta > 0.0 || far_strength > 0.0)) {
        return {"cap_k", "the failure envelope k + theta I1 - gamma exp(-B1 I1) never becomes "
                         "positive: no elastic region"};
    }
    return {};
}

std::unique_ptr<GeneralizedCap> GeneralizedCap::from_case(const io::CaseTable& table) {
    namespace dim = io::dimension;
    cap::Parameters p;
    p.k = table.quantity("cap_k", dim::kPressure);
    p.theta = table.number("cap_theta");
    p.gamma = table.quantity("cap_gamma", dim::kPressure);
    p.beta = table.quantity("cap_beta", dim::kInversePressure);
    p.D = table.quantity("cap_D", dim::kInversePressure);
    p.W = table.number("cap_W");
    p.X0 = table.quantity("cap_X0", dim::kPressure);
    p.R = table.number("cap_R");
    p.tension = table.positive_quantity_or("tension_cutoff", dim::kPressure, 0.0, true);
    const auto [key, message] = check(p);
    if (!key.empty()) {
        table.fail(key, message);
    }
    return std::make_unique<GeneralizedCap>(ElasticConstants::from_case(table), p);
}

std::vector<std::string> GeneralizedCap::state_names() const {
    return {"cap_position", "cap_center", "plastic_volumetric_strain", "equivalent_plastic_strain"};
}

void GeneralizedCap::initialise_state(std::span<double> state) const {
    // X0 below the apex / tension cutoff is lifted to it, so that L >= I1_min always holds.
    const cap::Parameters& p = model_.p;
    const double l = cap::cap_center_for(p, p.X0, p.X0);
    const double x = cap::cap_position(p, l);
    state[kCapPosition] = x;
    state[kCapCenter] = l;
    state[kPlasticVolumetricStrain] = p.W * (1.0 - cap::hardening_decay(p, x));
    state[kEquivalentPlasticStrain] = 0.0;
}

PlasticRegion GeneralizedCap::update(const Voigt6& strain_increment, Voigt6& stress,
                                     std::span<double> state, Matrix6* tangent) const {
    // Compression positive from here on: sigma_c = -sigma, deps_c = -deps. The tangent
    // d sigma / d deps = d sigma_c / d deps_c needs no sign change.
    const Voigt6 trial = -stress - elastic_.stiffness() * strain_increment;
    const double i1_tr = trial.head<3>().sum();
    Voigt6 s_tr = trial;
    s_tr.head<3>().array() -= i1_tr / 3.0;
    const double q_tr = root_j2(s_tr);

    const cap::Hardening before{state[kCapPosition], state[kCapCenter]};
    const cap::Return r = cap::return_map(model_, i1_tr, q_tr, before);

    Voigt6 sigma = r.rho * s_tr;
    sigma.head<3>().array() += r.i1 / 3.0;
    stress = -sigma;
    state[kCapPosition] = r.hardening.x;
    state[kCapCenter] = r.hardening.l;
    state[kPlasticVolumetricStrain] += r.hardening_strain;
    state[kEquivalentPlasticStrain] += equivalent_increment(elastic_, i1_tr, q_tr, r);
    if (tangent != nullptr) {
        *tangent = consistent_tangent(elastic_, r, s_tr, q_tr);
    }
    return r.region;
}

double GeneralizedCap::equivalent_plastic_strain(std::span<const double> state) const {
    return state[kEquivalentPlasticStrain];
}

} // namespace grainload::materials
