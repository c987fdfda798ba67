#pragma once
// The geostatic (at-rest) initial stress of a body under gravity, with lateral ratio K0.

#include "sph/particle_set.hpp"

namespace grainload::sph {

/// Geostatic (at-rest) initial stress of a body at rest under gravity g, particles
/// [first, size()) of `particles`: with up = -g/|g| and the depth d of a particle below the
/// body's top (its highest particle centre plus half a spacing),
///   sigma_v = -rho |g| d   (tension positive),   sigma = K0 sigma_v I + (1 - K0) sigma_v up up^T,
/// i.e. sigma_v along the vertical and K0 sigma_v in every horizontal direction (in plane
/// strain also out of plane). Exact vertical equilibrium for a body with a flat top whose
/// columns reach it (a box, a column); K0 is the lateral earth-pressure ratio at rest (Jaky:
/// 1 - sin phi; elastic, laterally confined: nu / (1 - nu)).
void set_geostatic_stress(ParticleSet& particles, Index first, const Vec3& gravity, double spacing,
                          double lateral_ratio);

} // namespace grainload::sph
