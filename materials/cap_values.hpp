#pragma once
// The values of the generalized cap's return: the material's constants, a point's hardening
// state and the outcome of its return.

#include "materials/cap_surfaces.hpp"
#include "materials/material.hpp"

namespace grainload::materials::cap {

/// Constants a return needs, fixed per material.
struct Model {
    Parameters p;
    double bulk = 0.0;
    double shear = 0.0;
    double i1_min = 0.0;    ///< minimum_pressure(p), cached
    double kappa_min = 0.0; ///< lowest_hardening(p, i1_min): the cap contracts no further
};

/// Hardening state of one point: cap position X and hardening parameter kappa,
/// X = kappa + R F(kappa); the centre L(kappa) and half-height B(kappa) follow from kappa.
struct Hardening {
    double x = 0.0;
    double kappa = 0.0;
};

/// Outcome of a return: final I1, radial factor rho, the Jacobian of (I1, rho) with respect to
/// the trial invariants (I1_tr, q_tr = sqrt(J2_tr)) for the consistent tangent, and the new
/// hardening state with its plastic volumetric strain increment (compaction positive).
struct Return {
    PlasticRegion region = PlasticRegion::elastic;
    double i1 = 0.0;
    double rho = 1.0;
    double di1_di1 = 1.0;
    double di1_dq = 0.0;
    double drho_di1 = 0.0;
    double drho_dq = 0.0;
    Hardening hardening;
    double hardening_strain = 0.0;
};

/// A plastic return's region, invariants and new hardening; the Jacobian is the region's to
/// fill in.
inline Return finish(PlasticRegion region, double i1, double rho, const Hardening& after,
                     double dv) {
    Return r;
    r.region = region;
    r.i1 = i1;
    r.rho = rho;
    r.hardening = after;
    r.hardening_strain = dv;
    return r;
}

} // namespace grainload::materials::cap
