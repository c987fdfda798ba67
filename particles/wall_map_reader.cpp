#include "particles/wall_map_reader.hpp"

#include "io/case_table.hpp"
#include "io/named_index.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace grainload::particles {

namespace dim = io::dimension;

namespace {

std::vector<int> read_walls(const io::CaseTable& table, std::span<const std::string> names) {
    std::vector<int> indices;
    for (const std::string& name : table.name_list("walls")) {
        const auto found = std::find(names.begin(), names.end(), name);
        if (found == names.end()) {
            std::string known;
            for (const std::string& other : names) {
                known += (known.empty() ? "" : ", ") + other;
            }
            table.fail("walls", "no wall called \"" + name + "\"; the walls are: " + known);
        }
        const auto index = static_cast<int>(found - names.begin());
        if (std::find(indices.begin(), indices.end(), index) != indices.end()) {
            table.fail("walls", "wall \"" + name + "\" is listed twice");
        }
        indices.push_back(index);
    }
    return indices;
}

Vec3 unit_vector(const io::CaseTable& table, const char* key) {
    const Vec3 v = table.vector(key, dim::kNone);
    if (!(v.norm() > 0.0)) {
        table.fail(key, "expected a non-zero vector");
    }
    return v.normalized();
}

void read_cylinder(const io::CaseTable& table, int dimension, WallMapSet::Map& map) {
    if (dimension != 3) {
        table.fail("type", "a cylinder map needs a 3D scene; in plane strain map a wall with "
                           "type = \"plane\"");
    }
    map.axis = unit_vector(table, "axis");
    // The default angle 0: the coordinate axis least aligned with the cylinder's, made normal.
    Vec3 reference = Vec3::UnitX();
    if (table.has("reference")) {
        reference = table.vector("reference", dim::kNone);
    } else {
        Eigen::Index least = 0;
        map.axis.cwiseAbs().minCoeff(&least);
        reference = Vec3::Unit(least);
    }
    reference -= reference.dot(map.axis) * map.axis;
    if (!(reference.norm() > 1e-9)) {
        table.fail("reference", "expected a direction not along the axis");
    }
    map.reference = reference.normalized();
    map.radius = table.positive_quantity("radius", dim::kLength);
    map.length = table.positive_quantity("length", dim::kLength);
    map.angle_start = 0.0;
    map.angle_end = 2.0 * std::numbers::pi;
    if (table.has("angles")) {
        const auto angles = table.quantity_list("angles", dim::kAngle);
        if (angles.size() != 2 || !(angles[1] > angles[0]) ||
            angles[1] - angles[0] > 2.0 * std::numbers::pi * (1.0 + 1e-12)) {
            table.fail("angles", "expected two angles, the start and a larger end, at most "
                                 "360 deg apart (e.g. \"0 90 deg\")");
        }
        map.angle_start = angles[0];
        map.angle_end = angles[1];
    }
}

void read_plane(const io::CaseTable& table, int dimension, WallMapSet::Map& map) {
    map.edge_u = table.vector("edge_u", dim::kLength);
    if (!(map.edge_u.norm() > 0.0)) {
        table.fail("edge_u", "expected a non-zero edge");
    }
    if (dimension == 2) {
        if (table.has("edge_v")) {
            table.fail("edge_v", "in plane strain a grid is edge_u by 1 m of depth: expected "
                                 "no edge_v");
        }
        return;
    }
    map.edge_v = table.vector("edge_v", dim::kLength);
    if (!(map.edge_u.cross(map.edge_v).norm() > 1e-9 * map.edge_u.norm() * map.edge_v.norm())) {
        table.fail("edge_v", "expected an edge not parallel to edge_u");
    }
}

void read_bins(const io::CaseTable& table, int dimension, WallMapSet::Map& map) {
    const auto bins = table.quantity_list("bins", dim::kNone);
    const auto whole = [](double b) { return b >= 1.0 && b <= 1e6 && b == std::floor(b); };
    if (bins.size() != 2 || !whole(bins[0]) || !whole(bins[1])) {
        table.fail("bins", "expected two whole numbers of cells from 1 to 1e6, e.g. [40, 36]");
    }
    map.bins_1 = static_cast<int>(bins[0]);
    map.bins_2 = static_cast<int>(bins[1]);
    if (!map.cylinder && dimension == 2 && map.bins_2 != 1) {
        table.fail("bins", "in plane strain a grid has one cell across the depth: expected [n, 1]");
    }
}

} // namespace

std::vector<WallMapSet::Map> read_wall_maps(const io::CaseTable& parent,
                                            std::span<const std::string> wall_names,
                                            int dimension) {
    std::vector<WallMapSet::Map> maps;
    for (const auto& table : parent.array_of_tables("wall_map")) {
        WallMapSet::Map map;
        map.name = table.string("name");
        io::refuse_repeated_name(table, maps, map.name, "wall map", &WallMapSet::Map::name);
        map.walls = read_walls(table, wall_names);
        map.half_spacing.assign(map.walls.size(), 0.0);
        map.cylinder = table.choice("type", {"cylinder", "plane"}) == "cylinder";
        map.origin = table.vector("origin", dim::kLength);
        if (map.cylinder) {
            read_cylinder(table, dimension, map);
        } else {
            read_plane(table, dimension, map);
        }
        read_bins(table, dimension, map);
        map.reach = table.positive_quantity_or("reach", dim::kLength,
                                               std::numeric_limits<double>::infinity());
        // By default the window is the whole run, however long a restart makes it.
        map.window_start = 0.0;
        map.window_end = std::numeric_limits<double>::infinity();
        if (table.has("window")) {
            const auto window = table.quantity_list("window", dim::kTime);
            if (window.size() != 2 || !(window[0] >= 0.0) || !(window[1] > window[0])) {
                table.fail("window", "expected two times, a start >= 0 and a later end (e.g. "
                                     "\"1.2 1.4 s\")");
            }
            map.window_start = window[0];
            map.window_end = window[1];
        }
        maps.push_back(std::move(map));
    }
    return maps;
}

} // namespace grainload::particles
