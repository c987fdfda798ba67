#pragma once
// The particle estimate of an SPH scene as the case's [sph] tables state it.

#include "materials/material_library.hpp"
#include "sph/particle_estimate.hpp"

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// The estimate of the [sph] table of `root` (empty when there is none), its bodies' materials
/// from `materials`. `dimension` 2 or 3.
ParticleEstimate estimate_particles(const io::CaseTable& root, int dimension,
                                    const materials::MaterialLibrary& materials);

} // namespace grainload::sph
