#include "materials/generalized_cap.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace grainload::materials {
namespace {

const Voigt6 kIdentity = (Voigt6() << 1.0, 1.0, 1.0, 0.0, 0.0, 0.0).finished();

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
    model_.kappa_min = cap::lowest_hardening(parameters, model_.i1_min);
}

namespace {

std::string pascals(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g Pa", value);
    return text;
}

} // namespace

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
    if (p.semantics == cap::Semantics::mat025) {
        const double lowest = cap::lowest_cap_position(p, cap::minimum_pressure(p));
        if (!(p.X0 >= lowest)) {
            return {"cap_X0",
                    "expected X0 >= " + pascals(lowest) +
                        ": with MAT_025 semantics X0 is the initial cap intercept, and the "
                        "cap (centre L = max(kappa, 0), half-width X - L) needs X0 >= 0 and X0 "
                        "at or above the envelope's apex (a flat cap, R = 0: X0 >= -T); "
                        "cap_semantics = \"lifted_x0\" lifts a lower X0 instead"};
        }
    }
    return {};
}

std::vector<std::string> GeneralizedCap::state_names() const {
    return {"cap_position", "hardening_parameter", "plastic_volumetric_strain",
            "equivalent_plastic_strain"};
}

void GeneralizedCap::initialise_state(std::span<double> state) const {
    const cap::Parameters& p = model_.p;
    state[kEquivalentPlasticStrain] = 0.0;
    if (p.semantics == cap::Semantics::mat025) {
        // MAT_025: X0 is the initial intercept, X(kappa0) = X0 (kappa0 < 0 when F(0) > 0 and X0
        // is small), and eps_v^p starts at 0 (check() guaranteed X0 >= X(kappa_min)).
        state[kCapPosition] = p.X0;
        state[kHardeningParameter] = cap::hardening_for(p, p.X0, p.X0, model_.kappa_min);
        state[kPlasticVolumetricStrain] = 0.0;
        return;
    }
    // lifted_x0: X0 below X(I1_min) (apex / tension cutoff) is lifted to it, so that
    // L = kappa >= I1_min always holds, and eps_v^p starts at the law's value there.
    const double floor = model_.i1_min;
    const double kappa =
        cap::cap_position(p, floor) >= p.X0 ? floor : cap::hardening_for(p, p.X0, p.X0, floor);
    const double x = cap::cap_position(p, kappa);
    state[kCapPosition] = x;
    state[kHardeningParameter] = kappa;
    state[kPlasticVolumetricStrain] = p.W * (1.0 - cap::hardening_decay(p, x));
}

void GeneralizedCap::trial(const Voigt6& strain_increment, const Voigt6& stress, Trial& t) const {
    // Compression positive from here on: sigma_c = -sigma, deps_c = -deps. The tangent
    // d sigma / d deps = d sigma_c / d deps_c needs no sign change.
    // Component by component in scalars, with the operations and order of the Voigt expressions
    // -stress - stress_from_strain(deps), head<3>().sum() and sqrt(0.5 |s_n|^2 + |s_s|^2) that it
    // replaces (the same bits): GCC stored those temporaries in 8-byte pieces and read them back
    // in 16-byte ones, which the processor cannot forward.
    const double shear = elastic_.shear_modulus;
    const double lambda = elastic_.lame_lambda();
    double diagonal = lambda;
    diagonal += 2.0 * shear;
    const double e0 = strain_increment[0];
    const double e1 = strain_increment[1];
    const double e2 = strain_increment[2];
    double s[6];
    for (int i = 0; i < 3; ++i) {
        double sum = (i == 0 ? diagonal : lambda) * e0;
        sum += (i == 1 ? diagonal : lambda) * e1;
        sum += (i == 2 ? diagonal : lambda) * e2;
        s[i] = -stress[i] - sum;
        s[i + 3] = -stress[i + 3] - shear * strain_increment[i + 3];
    }
    t.i1 = (s[0] + s[1]) + s[2];
    const double third = t.i1 / 3.0;
    for (int i = 0; i < 3; ++i) {
        s[i] -= third;
    }
    t.q = std::sqrt(0.5 * ((s[0] * s[0] + s[1] * s[1]) + s[2] * s[2]) +
                    ((s[3] * s[3] + s[4] * s[4]) + s[5] * s[5]));
    for (int i = 0; i < 6; ++i) {
        t.deviator[i] = s[i];
    }
}

void GeneralizedCap::apply(const Trial& t, const cap::Return& r, Voigt6& stress,
                           double* state) const {
    // Component by component, as rho s_tr + (I1/3) 1 with the sign turned (trial's reason).
    const double third = r.i1 / 3.0;
    for (int i = 0; i < 3; ++i) {
        stress[i] = -(r.rho * t.deviator[i] + third);
        stress[i + 3] = -(r.rho * t.deviator[i + 3]);
    }
    state[kCapPosition] = r.hardening.x;
    state[kHardeningParameter] = r.hardening.kappa;
    state[kPlasticVolumetricStrain] += r.hardening_strain;
    state[kEquivalentPlasticStrain] += equivalent_increment(elastic_, t.i1, t.q, r);
}

PlasticRegion GeneralizedCap::update(const Voigt6& strain_increment, Voigt6& stress,
                                     std::span<double> state, Matrix6* tangent) const {
    Trial t;
    trial(strain_increment, stress, t);
    const cap::Hardening before{state[kCapPosition], state[kHardeningParameter]};
    const cap::Return r = cap::return_map(model_, t.i1, t.q, before);
    apply(t, r, stress, state.data());
    if (tangent != nullptr) {
        *tangent = consistent_tangent(elastic_, r, t.deviator, t.q);
    }
    return r.region;
}

void GeneralizedCap::update_points(std::span<const Voigt6> strain_increments, double,
                                   std::span<Voigt6> stresses, std::span<double* const> states,
                                   std::span<PlasticRegion> regions) const {
    const std::size_t n = stresses.size();
    // Buffers of each thread, kept between calls: the SPH stress update calls this for every
    // block of 64 particles, and five allocations a block were a few per cent of the cap's step.
    thread_local std::vector<Trial> trials;
    thread_local std::vector<double> i1;
    thread_local std::vector<double> q;
    thread_local std::vector<cap::Hardening> before;
    thread_local std::vector<cap::Return> returns;
    trials.resize(n);
    i1.resize(n);
    q.resize(n);
    before.resize(n);
    returns.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        trial(strain_increments[k], stresses[k], trials[k]);
        i1[k] = trials[k].i1;
        q[k] = trials[k].q;
        before[k] = {states[k][kCapPosition], states[k][kHardeningParameter]};
    }
    cap::return_map_many(model_, i1, q, before, returns);
    for (std::size_t k = 0; k < n; ++k) {
        apply(trials[k], returns[k], stresses[k], states[k]);
        regions[k] = returns[k].region;
    }
}

double GeneralizedCap::equivalent_plastic_strain(std::span<const double> state) const {
    return state[kEquivalentPlasticStrain];
}

} // namespace grainload::materials
