#pragma once
// The mu(I) local rheology of dense granular flow (Jop, Forterre & Pouliquen 2006).

#include "io/types.hpp"

namespace grainload::materials {

/// The local rheology of dense granular flow, mu(I) (GDR MiDi 2004; Jop, Forterre & Pouliquen
/// 2006, Nature 441, eqs. 1-2): the ratio of shear stress to pressure grows with the inertial
/// number I from the static friction mu_s to the limit mu_2,
///
///     mu(I) = mu_s + (mu_2 - mu_s) / (I0 / I + 1),     I = gamma_dot d / sqrt(p / rho_s),
///
/// with d the grain diameter, rho_s the density of the grains' solid (not the bulk density) and
/// gamma_dot = sqrt(2 D':D') the shear rate of Jop et al. (their |gamma_dot| =
/// sqrt(gamma_ij gamma_ij / 2) with gamma_ij = 2 D_ij), which is du/dy in simple shear.
/// Equations and sources in docs/theory/mu_i.md.
struct MuILaw {
    double mu_s = 0.0;           ///< static friction, mu(0)
    double mu_2 = 0.0;           ///< limit friction, mu(infinity); mu_2 >= mu_s
    double i0 = 0.0;             ///< I at which mu is half-way from mu_s to mu_2
    double grain_diameter = 0.0; ///< d, m
    double grain_density = 0.0;  ///< rho_s, kg/m^3

    /// I of a shear rate (1/s) at a pressure p (Pa, compression positive): 0 without shear
    /// (the material at rest, at any pressure); infinity for a shear at p <= 0 (no confinement).
    double inertial_number(double shear_rate, double pressure) const;
    /// mu(I), with its limits mu(0) = mu_s exactly and mu(infinity) = mu_2.
    double friction(double inertial_number) const;
    /// The inverse of friction(): I = I0 (mu - mu_s) / (mu_2 - mu), 0 for mu <= mu_s (no flow
    /// below the static friction) and infinity for mu >= mu_2 (no rate reaches it).
    double inertial_number_at(double friction) const;
    /// dI/dmu of inertial_number_at() for mu_s < mu < mu_2: I0 (mu_2 - mu_s) / (mu_2 - mu)^2.
    double inertial_number_slope(double friction) const;
};

/// gamma_dot = sqrt(2 D':D') of a strain increment (Voigt, engineering shears) over time_step:
/// the deviatoric part only, so that a volume change alone is no shear. 0 when time_step is
/// infinite (the quasi-static limit).
double shear_rate(const Voigt6& strain_increment, double time_step);

} // namespace grainload::materials
