#include "sph/wall_bodies.hpp"

#include "io/case_table.hpp"

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

std::vector<int> read_wall_bodies(const io::CaseTable& table,
                                  const std::vector<std::string>& body_names) {
    std::vector<int> bodies;
    if (!table.has("bodies")) {
        return bodies;
    }
    std::string known;
    for (const std::string& name : body_names) {
        known += (known.empty() ? "\"" : ", \"") + name + "\"";
    }
    for (const std::string& name : table.name_list("bodies")) {
        const auto found = std::find(body_names.begin(), body_names.end(), name);
        if (found == body_names.end()) {
            table.fail("bodies", "no [[sph.body]] called \"" + name +
                                     "\": expected names of bodies (" + known + ")");
        }
        const auto id = static_cast<int>(found - body_names.begin());
        if (std::find(bodies.begin(), bodies.end(), id) != bodies.end()) {
            table.fail("bodies", "body \"" + name + "\" is listed twice: expected each once");
        }
        bodies.push_back(id);
    }
    return bodies;
}

} // namespace grainload::sph
