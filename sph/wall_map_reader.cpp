#include "sph/wall_map_reader.hpp"

#include "io/case_table.hpp"
#include "particles/wall_map_reader.hpp"

#include <cmath>
#include <string>

namespace grainload::sph {

particles::WallMapSet read_wall_maps(const io::CaseTable& sph, const ParticleSet& set,
                                     const std::vector<Wall>& walls, int dimension) {
    std::vector<std::string> names;
    for (const Wall& wall : walls) {
        names.push_back(wall.name);
    }
    std::vector<particles::WallMapSet::Map> maps = particles::read_wall_maps(sph, names, dimension);
    const auto tables = sph.array_of_tables("wall_map");
    for (std::size_t k = 0; k < maps.size(); ++k) {
        particles::WallMapSet::Map& map = maps[k];
        for (std::size_t m = 0; m < map.walls.size(); ++m) {
            const Wall& wall = walls[static_cast<std::size_t>(map.walls[m])];
            if (wall.normals.size() != static_cast<std::size_t>(wall.count)) {
                tables[k].fail("walls", "wall \"" + wall.name +
                                            "\" has no surface normals, which a map needs to "
                                            "split its load into pressure and friction");
            }
            // add_wall gives a wall particle the mass density x spacing^dimension.
            if (wall.count > 0) {
                const double spacing =
                    std::pow(set.mass[wall.first] / set.density[wall.first], 1.0 / dimension);
                map.half_spacing[m] = 0.5 * spacing;
            }
        }
    }
    return particles::WallMapSet(std::move(maps));
}

} // namespace grainload::sph
