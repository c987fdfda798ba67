#include "sph/wall_bodies.hpp"

#include <algorithm>

namespace grainload::sph {

WallBodyFilter wall_body_filter(const std::vector<Wall>& walls) {
    WallBodyFilter filter;
    const bool any = std::any_of(walls.begin(), walls.end(),
                                 [](const Wall& wall) { return !wall.bodies.empty(); });
    if (!any) {
        return filter;
    }
    // Wall ids follow the bodies' (add_wall), so the largest wall id bounds every body id,
    // bodies a source adds later included.
    for (const Wall& wall : walls) {
        filter.groups = std::max(filter.groups, wall.body_id + 1);
    }
    const auto groups = static_cast<std::size_t>(filter.groups);
    filter.apart.assign(groups * groups, 0);
    for (const Wall& wall : walls) {
        if (wall.bodies.empty()) {
            continue;
        }
        const auto w = static_cast<std::size_t>(wall.body_id);
        for (std::size_t b = 0; b < groups; ++b) {
            const bool acts = std::find(wall.bodies.begin(), wall.bodies.end(),
                                        static_cast<int>(b)) != wall.bodies.end();
            filter.apart[w * groups + b] = acts ? 0 : 1;
            filter.apart[b * groups + w] = acts ? 0 : 1;
        }
    }
    return filter;
}

} // namespace grainload::sph
