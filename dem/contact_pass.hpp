#pragma once
// One evaluation of every grain's force and torque: gravity, the grain pairs, the walls.

#include "dem/contact_law.hpp"
#include "dem/grain_set.hpp"
#include "dem/plane_wall.hpp"
#include "particles/neighbour_list.hpp"

#include <span>
#include <vector>

namespace grainload::dem {

/// What the pass saw, for the books and the diagnosis.
struct ContactBooks {
    double elastic_energy = 0.0; ///< held in the contacts' springs [J]
    Index pair_contacts = 0;
    Index wall_contacts = 0;
    double deepest_overlap = 0.0; ///< overlap / the smaller radius, largest over the contacts
    Index deepest_grain = -1;
};

/// The scene's fixed inputs to the pass.
struct ContactScene {
    const ContactLaw& law;
    std::span<const GrainElastic> body_elastic; ///< by body id
    Vec3 gravity;
};

/// Set grains.force, torque, contacts and springs at the current positions and velocities.
/// Each pair is evaluated in both grains' rows, oriented from the grain of the lower id, so
/// that the rows run in parallel with no shared writes and the two forces are exact opposites
/// (momentum kept to round-off); the spring is kept by the lower id. Then the walls, grain by
/// grain, with walls[w].force their sum. `neighbours` must be current for the positions.
ContactBooks evaluate_contacts(GrainSet& grains, const particles::NeighbourList& neighbours,
                               std::vector<PlaneWall>& walls, const ContactScene& scene,
                               double time_step);

} // namespace grainload::dem
