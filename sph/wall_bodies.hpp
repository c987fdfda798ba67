#pragma once
// Which bodies each wall acts on (a wall's bodies key), as a filter over particle pairs.

#include "sph/wall.hpp"

#include <string>
#include <vector>

namespace grainload::sph {

/// Which body-wall pairs of particles never interact (Wall::bodies): a table over the
/// particles' body ids (ParticleSet::body_id; a wall's particles carry the wall's), apart[a *
/// groups + b] nonzero when ids a and b are kept apart. Empty when every wall acts on every
/// body: the solver then does no work for it at all.
struct WallBodyFilter {
    int groups = 0;
    std::vector<char> apart;
    bool empty() const { return apart.empty(); }
};

/// The filter of `walls`: each wall with a `bodies` list is kept apart from every other id
/// below the largest wall id (walls never pair with each other anyway).
WallBodyFilter wall_body_filter(const std::vector<Wall>& walls);

} // namespace grainload::sph
