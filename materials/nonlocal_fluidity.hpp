#pragma once
// The non-local granular fluidity on a mu(I) law: its local fluidity, its cooperativity length
// and the viscoplastic return that flows at the fluidity's rate.

#include "materials/drucker_prager_return.hpp"
#include "materials/elastic_constants.hpp"
#include "materials/material.hpp"
#include "materials/mu_i_law.hpp"

#include <span>

namespace grainload::materials {

/// The non-local granular fluidity model (Kamrin & Koval 2012, PRL 108, 178301; Henann &
/// Kamrin 2013, PNAS 110, 6730) on the mu(I) law of Jop, Forterre & Pouliquen (2006). The
/// fluidity g = gamma_dot^p / mu is the plastic shear rate per unit stress ratio; it obeys
///
///     g = g_loc(mu, p) + xi(mu)^2 laplacian(g),        xi = A d / sqrt|mu - mu_s|,
///
/// with g_loc the fluidity of the local law, gamma_dot(mu, p) / mu where gamma_dot is mu(I)
/// solved for the rate (0 below mu_s), and xi the cooperativity length, which diverges at the
/// static friction: near yield, flow spreads over xi into material that the local law holds
/// still (creep beside a shear band, size effects at an outlet). Where g is uniform the model is
/// the local mu(I). A, the non-local amplitude, is a material constant of order 1 (Henann &
/// Kamrin fit it on split-bottom cell flows). Equations and discretisation in
/// docs/theory/mu_i.md, "Non-local fluidity".
///
/// A point's fluidity is g_loc at the step's stress plus its non-local excess g - g_loc, which
/// the particle method solves for over the neighbours (sph/fluidity_field.hpp) and writes into
/// the point's state before the update; without it (a material-point driver, a shell) the
/// excess is 0 and the model is the local viscoplastic mu(I).
struct NonlocalFluidity {
    MuILaw law;
    double amplitude = 0.0; ///< A, dimensionless
    /// The state entries of a point (the material's layout): the inertial number of its last
    /// flow, the fluidity its last update flowed at (1/s; for output and as the start of the
    /// next solve) and the non-local excess of the coming update (1/s).
    int inertial_index = 0;
    int fluidity_index = 0;
    int excess_index = 0;

    /// g_loc = gamma_dot_loc / mu at stress ratio mu and pressure p, gamma_dot_loc =
    /// I(mu) sqrt(p / rho_s) / d the local law's rate (0 for mu <= mu_s or p <= 0), the
    /// inertial number capped at kMaximumInertialNumber (the source of the field equation stays
    /// finite where mu reaches mu_2).
    double local_fluidity(double mu, double pressure) const;
    /// 1 / xi^2 = |mu - mu_s| / (A d)^2, 1/m^2: finite at mu = mu_s, where xi diverges.
    double screening(double mu) const;
};

/// Beyond I = 10 the flow is a collisional gas (GDR MiDi 2004 places the dense regime below
/// I = 0.1-0.3): the field's source is capped there.
inline constexpr double kMaximumInertialNumber = 10.0;

/// The viscoplastic return of the fluidity model over a step of dt seconds from the elastic
/// trial: the deviatoric stress relaxes at the fluidity's plastic rate,
///
///     tau = tau_tr - G dt gamma_dot^p(tau),   gamma_dot^p = max(0, gamma_dot_loc(mu) + excess mu),
///
/// with mu = tau / p, tau = sqrt(J2), at the trial pressure (isochoric flow, as the local mu(I)
/// material's), solved for tau by safeguarded Newton (the local part implicit: the explicit
/// fluidity of the step's start oscillates wherever G dt g / p exceeds 1, which is everywhere in
/// a flowing SPH body). Where p <= 0 the point returns to the apex of the static cone. Adds
/// to the DruckerPrager state entries 0 and 1, writes the inertial number of the flow at
/// inertial_index and the fluidity flowed at, gamma_dot^p / mu, at fluidity_index. The tangent, on
/// request, is the elastic one with the deviatoric part scaled by tau / tau_tr.
PlasticRegion fluidity_return(const ElasticConstants& elastic, const NonlocalFluidity& fluidity,
                              const DruckerPragerTrial& trial, double dt, Voigt6& stress,
                              std::span<double> state, Matrix6* tangent);

} // namespace grainload::materials
