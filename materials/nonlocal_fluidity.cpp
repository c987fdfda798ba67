#include "materials/nonlocal_fluidity.hpp"

#include "materials/voigt_algebra.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainload::materials {

namespace {

constexpr int kPlasticStrain = 0;
/// The Newton iteration stops when the bracket or the step is below this fraction of tau_tr:
/// round-off of the stress itself.
constexpr double kRelativeTolerance = 1e-13;
constexpr int kMaximumIterations = 200;

/// The step's plastic rate at shear stress tau and its derivative d/dtau (both at pressure p).
struct PlasticRate {
    double rate = 0.0;
    double slope = 0.0;
};

PlasticRate plastic_rate(const NonlocalFluidity& fluidity, double tau, double pressure,
                         double excess) {
    const double mu = tau / pressure;
    const MuILaw& law = fluidity.law;
    const double scale = std::sqrt(pressure / law.grain_density) / law.grain_diameter;
    double rate = excess * mu;
    double slope = excess;
    if (mu > law.mu_s) {
        rate += law.inertial_number_at(mu) * scale;
        slope += law.inertial_number_slope(mu) * scale;
    }
    if (!(rate > 0.0)) {
        return {0.0, 0.0};
    }
    return {rate, slope / pressure};
}

/// The root of F(tau) = tau - tau_tr + G dt rate(tau) in (0, upper), F(0) < 0 < F(upper): Newton
/// steps kept inside the bracket, bisection where a step would leave it (Press et al.,
/// Numerical Recipes, rtsafe).
double relaxed_shear(const NonlocalFluidity& fluidity, double tau_trial, double upper,
                     double pressure, double excess, double stiffness_dt, double start) {
    double low = 0.0;
    double high = upper;
    double tau =
        start > 0.0 && start < upper ? start : std::min(tau_trial, fluidity.law.mu_s * pressure);
    const double tolerance = kRelativeTolerance * tau_trial;
    for (int iteration = 0; iteration < kMaximumIterations; ++iteration) {
        const PlasticRate at = plastic_rate(fluidity, tau, pressure, excess);
        const double residual = tau - tau_trial + stiffness_dt * at.rate;
        if (residual == 0.0) {
            return tau;
        }
        (residual < 0.0 ? low : high) = tau;
        const double newton = tau - residual / (1.0 + stiffness_dt * at.slope);
        if (std::abs(newton - tau) <= tolerance) {
            return newton;
        }
        // F is convex (the rate is, and so its maximum with 0): a Newton step from above the
        // root stays above it, one from below lands above it or beyond the bracket.
        const bool inside = newton >= low && newton <= high && std::isfinite(newton);
        const double next = inside ? newton : 0.5 * (low + high);
        if (high - low <= tolerance) {
            return next;
        }
        tau = next;
    }
    return tau;
}

} // namespace

double NonlocalFluidity::local_fluidity(double mu, double pressure) const {
    if (!(mu > law.mu_s) || !(pressure > 0.0)) {
        return 0.0;
    }
    const double inertial = std::min(law.inertial_number_at(mu), kMaximumInertialNumber);
    return inertial * std::sqrt(pressure / law.grain_density) / law.grain_diameter /
           std::min(mu, law.mu_2);
}

double NonlocalFluidity::screening(double mu) const {
    const double length = amplitude * law.grain_diameter;
    return std::abs(mu - law.mu_s) / (length * length);
}

PlasticRegion fluidity_return(const ElasticConstants& elastic, const NonlocalFluidity& fluidity,
                              const DruckerPragerTrial& trial, double dt, Voigt6& stress,
                              std::span<double> state, Matrix6* tangent) {
    const double pressure = -trial.i1 / 3.0;
    const double excess = state[fluidity.excess_index];
    const double shear = elastic.shear_modulus;
    if (!(pressure > 0.0) || !(trial.sqrt_j2 > 0.0)) {
        // No confinement: the static cone's apex return (cohesionless, the stress goes to 0).
        state[fluidity.inertial_index] = std::numeric_limits<double>::quiet_NaN();
        state[fluidity.fluidity_index] = 0.0;
        const DruckerPragerCone apex{fluidity.law.mu_s / 3.0, 0.0, 0.0, 0.0};
        return drucker_prager_return(elastic, apex, trial, stress, state, tangent);
    }
    const double tau_trial = trial.sqrt_j2;
    if (plastic_rate(fluidity, tau_trial, pressure, excess).rate == 0.0) {
        stress = trial.stress;
        state[fluidity.inertial_index] = 0.0;
        state[fluidity.fluidity_index] = 0.0;
        if (tangent != nullptr) {
            *tangent = elastic.stiffness();
        }
        return PlasticRegion::elastic;
    }
    const double upper = std::min(tau_trial, fluidity.law.mu_2 * pressure);
    // A flowing point flows next step at nearly the same stress ratio: Newton starts from the
    // ratio of the inertial number it last flowed at (2 to 3 iterations instead of 6 to 8).
    const double last = state[fluidity.inertial_index];
    const double start = last > 0.0 ? fluidity.law.friction(last) * pressure : 0.0;
    const double tau =
        relaxed_shear(fluidity, tau_trial, upper, pressure, excess, shear * dt, start);
    const double ratio = tau / tau_trial;
    stress = ratio * trial.deviator + (trial.i1 / 3.0) * voigt::identity();
    // |s_tr - s| = sqrt2 (tau_tr - tau): the DruckerPrager return's sqrt(2/3) |de^p| convention.
    state[kPlasticStrain] += (tau_trial - tau) / (std::sqrt(3.0) * shear);
    const double mu = tau / pressure;
    state[fluidity.inertial_index] = fluidity.law.inertial_number_at(mu);
    state[fluidity.fluidity_index] =
        mu > 0.0 ? plastic_rate(fluidity, tau, pressure, excess).rate / mu : 0.0;
    if (tangent != nullptr) {
        *tangent = elastic.stiffness() -
                   (1.0 - ratio) * voigt::deviatoric_stiffness(elastic.shear_modulus);
    }
    return PlasticRegion::failure_surface;
}

} // namespace grainload::materials
