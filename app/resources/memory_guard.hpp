#pragma once
// The refusal of a scene too large for the machine's memory, before any particle is made.

#include "io/case_table.hpp"
#include "materials/material_library.hpp"

#include <optional>

namespace grainload::app {

/// Bytes the machine can give a new process without swapping: MemAvailable of /proc/meminfo.
/// std::nullopt where the kernel does not say (then nothing is refused).
std::optional<double> available_memory();

/// Refuses, before any particle or shell node is made, a scene whose SPH particles
/// (sph/particle_estimate.hpp) and generated shells would need more than `available` bytes:
/// io::CaseError at the spacing key of the largest body or wall, with the estimate and the
/// spacing that would fit, or, when the shells take more than the particles, at the element
/// count of the largest shell. Returns the SPH particles that still fit beside the estimate
/// (the budget of the wall particles a [coupling] lays on its shells, which the shell mesh
/// must exist to count: coupling::read_coupled_model), std::nullopt when `available` is.
std::optional<double> refuse_oversized_scene(const io::CaseTable& root, int dimension,
                                             const materials::MaterialLibrary& materials,
                                             std::optional<double> available);

} // namespace grainload::app
