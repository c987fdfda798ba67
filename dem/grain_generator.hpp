#pragma once
// Grains placed at random in a box, none overlapping another: a loose packing to settle.

#include "dem/dem_case_reader.hpp"
#include "dem/grain_set.hpp"

namespace grainload::dem {

/// Append the grains of `body` (id `body_id`, grain density `density`) to `grains`: one at its
/// centre, or `count` by random sequential addition in its box (Widom 1966): each grain's
/// radius drawn uniformly in [radius_min, radius_max] as in Lazarevic et al. (2002, eq. 1), its
/// centre uniformly where it lies wholly inside the box, kept when it overlaps no grain placed
/// before (of any body), else drawn again (the radius kept, so that the sizes follow their
/// distribution; ten thousand draws of the centre before the box is called full). A loose packing
/// (up to about 0.3 of the box by volume) that gravity then settles. The draws follow a 64-bit
/// Mersenne twister seeded by `seed`: equal seeds give equal packings on every machine. Throws
/// io::CaseError naming the body when the box cannot hold the count.
void place_grains(const BodySettings& body, int body_id, double density, GrainSet& grains);

} // namespace grainload::dem
