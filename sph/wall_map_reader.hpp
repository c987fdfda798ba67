#pragma once
// The [[sph.wall_map]] tables of a case, read into the SPH scene's wall-load maps.

#include "particles/wall_map.hpp"
#include "sph/particle_set.hpp"
#include "sph/wall.hpp"

#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// The [[sph.wall_map]] tables of `sph` (particles/wall_map_reader.hpp, its keys
/// particles::kWallMapKeys); wall names resolve against `walls`, each of which must have
/// surface normals, and whose particles (in `set`) give the patch each particle's load
/// stands for: one spacing wide.
particles::WallMapSet read_wall_maps(const io::CaseTable& sph, const ParticleSet& set,
                                     const std::vector<Wall>& walls, int dimension);

} // namespace grainload::sph
