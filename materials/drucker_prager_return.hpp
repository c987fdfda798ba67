#pragma once
// The closed-form return map of a perfectly plastic Drucker-Prager cone, with its tangent.

#include "materials/elastic_constants.hpp"
#include "materials/material.hpp"

#include <limits>
#include <span>

namespace grainload::materials {

/// The constants of one Drucker-Prager cone, tension-positive I1 (docs/theory/materials.md):
/// yield f = sqrt(J2) + alpha I1 - k, potential g = sqrt(J2) + alpha_flow I1, cutoff I1 <= T.
struct DruckerPragerCone {
    double alpha = 0.0;      ///< friction coefficient on I1
    double k = 0.0;          ///< cohesion term, Pa
    double alpha_flow = 0.0; ///< dilatancy coefficient on I1 in the potential
    double tension_cutoff = std::numeric_limits<double>::infinity(); ///< T on I1, Pa
};

/// The elastic predictor of one update and its invariants.
struct DruckerPragerTrial {
    Voigt6 stress;
    Voigt6 deviator;
    double i1 = 0.0;
    double sqrt_j2 = 0.0;
};

/// sigma_tr = sigma_n + D_e d_eps (engineering shear strains) and its I1, s and sqrt(J2).
DruckerPragerTrial drucker_prager_trial(const ElasticConstants& elastic, const Voigt6& stress,
                                        const Voigt6& strain_increment);

/// The closed-form return of the perfectly plastic cone from `trial` (elastic, cone, cutoff face
/// or corner; derivation and tangents in docs/theory/materials.md). Writes the stress, adds the
/// step's plastic strains to state[0] (equivalent plastic strain) and state[1] (plastic
/// volumetric strain) and, on request, the consistent tangent. The cone needs
/// tension_cutoff <= k / alpha (DruckerPrager clamps it).
PlasticRegion drucker_prager_return(const ElasticConstants& elastic, const DruckerPragerCone& cone,
                                    const DruckerPragerTrial& trial, Voigt6& stress,
                                    std::span<double> state, Matrix6* tangent);

} // namespace grainload::materials
