#pragma once
// The removal of particles from a ParticleSet: every field and wall range compacted in order.

#include "particles/compact.hpp"
#include "sph/particle_set.hpp"
#include "sph/wall.hpp"

#include <span>
#include <vector>

namespace grainload::sph {

/// Remove the particles with gone[i] != 0 from `particles` (material or wall particles alike):
/// every field is compacted in order, the material state with it (each kept particle's block
/// moves down and its state_offset with it), and each wall's range [first, first + count) and
/// its per-particle arrays (normals, angular velocities, samples) follow, so a wall whose
/// particles all went keeps its place with count 0. Returns the old-to-new index map (-1 for
/// a removed particle). The caller rebuilds what indexes particles (the neighbour list).
std::vector<Index> remove_particles(ParticleSet& particles, std::span<const char> gone,
                                    std::vector<Wall>& walls);

} // namespace grainload::sph
