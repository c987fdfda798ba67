#pragma once
// The exact return map of the perfectly plastic Mohr-Coulomb hexagon in principal stresses.

#include "materials/elastic_constants.hpp"
#include "materials/material.hpp"

namespace grainload::materials {

/// The Mohr-Coulomb surface, tension positive, principal stresses s1 >= s2 >= s3:
///     yield      f = (s1 - s3) + (s1 + s3) sin(phi) - 2 c cos(phi) <= 0,
///     potential  g = (s1 - s3) + (s1 + s3) sin(psi),
/// six planes in principal stress space (one per ordering), meeting on the compression and
/// extension meridians (the hexagon's corners) and at the apex s1 = s2 = s3 = c cot(phi).
struct MohrCoulombSurface {
    double sin_phi = 0.0;
    double cos_phi = 1.0;
    double sin_psi = 0.0;
    double cohesion = 0.0; ///< c, Pa

    /// The apex's principal stress c cot(phi), Pa.
    double apex() const { return cohesion * cos_phi / sin_phi; }
    /// f of ordered principal stresses.
    double yield(const Vec3& s) const;
};

/// Where a principal return ended, its stresses and d s / d s_trial.
struct PrincipalReturn {
    PlasticRegion region = PlasticRegion::elastic;
    Vec3 stress = Vec3::Zero();
    Mat3 jacobian = Mat3::Identity();
};

/// The return of ordered trial principal stresses onto the hexagon (Koiter's rule at its
/// corners: two planes active, each with its own multiplier), in closed form because the
/// material is perfectly plastic: the main plane; else the corner the main return crossed
/// into (compression meridian s1 = s2, extension meridian s2 = s3) when both multipliers come
/// out non-negative; else the apex. Derivation in docs/theory/materials.md. The returned
/// region is failure_surface for a plane, corner for a meridian, apex for the apex.
PrincipalReturn mohr_coulomb_principal_return(const ElasticConstants& elastic,
                                              const MohrCoulombSurface& surface, const Vec3& trial);

} // namespace grainload::materials
