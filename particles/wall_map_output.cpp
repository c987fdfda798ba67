// WallMapSet's files and summary figures (see particles/wall_map.hpp).
#include "io/atomic_file.hpp"
#include "particles/wall_map.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <ostream>

namespace grainload::particles {

namespace {

/// The two coordinate columns and the traction columns' names of a map.
struct Columns {
    const char* first;
    const char* second;
    const char* traction_1;
    const char* traction_2;
    const char* name_1; ///< the coordinates in summary figure names
    const char* name_2;
};

Columns columns(const WallMapSet::Map& map) {
    if (map.cylinder) {
        return {"axial_m", "angle_deg", "shear_axial", "shear_circumferential", "axial", "angle"};
    }
    return {"u_m", "v_m", "shear_u", "shear_v", "u", "v"};
}

std::string map_file(const std::string& directory, const std::string& stem) {
    const std::filesystem::path folder = std::filesystem::path(directory) / "wall_maps";
    std::filesystem::create_directories(folder);
    return (folder / (stem + ".csv")).string();
}

} // namespace

void WallMapSet::write_interval(const Map& map, double time, double length,
                                const std::string& directory) const {
    char stem[32];
    std::snprintf(stem, sizeof stem, "_%06.0f", instants_);
    const Columns c = columns(map);
    io::write_file_atomically(map_file(directory, map.name + stem), [&](std::ostream& out) {
        out << std::setprecision(std::numeric_limits<double>::max_digits10);
        out << "time_s,interval_s," << c.first << ',' << c.second << ",pressure_Pa," << c.traction_1
            << "_Pa," << c.traction_2 << "_Pa\n";
        for (int cell = 0; cell < map.cells(); ++cell) {
            const auto at = map.centre(cell);
            const Load& load = map.interval[static_cast<std::size_t>(cell)];
            out << time << ',' << length << ',' << at[0] << ',' << at[1] << ',' << load[0] << ','
                << load[1] << ',' << load[2] << '\n';
        }
    });
}

void WallMapSet::write_window(const Map& map, const std::string& directory) const {
    const Columns c = columns(map);
    io::write_file_atomically(map_file(directory, map.name + "_window"), [&](std::ostream& out) {
        out << std::setprecision(std::numeric_limits<double>::max_digits10);
        out << "window_start_s,window_end_s," << c.first << ',' << c.second
            << ",mean_pressure_Pa,max_pressure_Pa,mean_" << c.traction_1 << "_Pa,max_"
            << c.traction_1 << "_Pa,mean_" << c.traction_2 << "_Pa,max_" << c.traction_2 << "_Pa\n";
        const double end = std::min(last_time_, map.window_end);
        for (int cell = 0; cell < map.cells(); ++cell) {
            const auto at = map.centre(cell);
            const Load mean = window_mean(map, cell);
            const Load& top = map.window_max[static_cast<std::size_t>(cell)];
            out << map.window_start << ',' << end << ',' << at[0] << ',' << at[1];
            for (int k = 0; k < 3; ++k) {
                out << ',' << mean[k] << ',' << top[k];
            }
            out << '\n';
        }
    });
}

void WallMapSet::append_results(std::vector<io::ResultFigure>& results) const {
    for (const Map& map : maps_) {
        const std::string prefix = "wall_map_" + map.name + "_";
        // Plane strain: forces and areas are both per metre of depth, pressures in Pa.
        const char* unit = "Pa";
        // Resultants of the window's mean: pressure and tractions times the cells' areas.
        Load total{};
        double peak_mean = -std::numeric_limits<double>::infinity();
        double peak_max = peak_mean;
        int at_mean = 0;
        int at_max = 0;
        for (int cell = 0; cell < map.cells(); ++cell) {
            const Load mean = window_mean(map, cell);
            for (int k = 0; k < 3; ++k) {
                total[k] += mean[k] * map.cell_area();
            }
            if (mean[0] > peak_mean) {
                peak_mean = mean[0];
                at_mean = cell;
            }
            const double top = map.window_max[static_cast<std::size_t>(cell)][0];
            if (top > peak_max) {
                peak_max = top;
                at_max = cell;
            }
        }
        const Columns c = columns(map);
        const auto where_mean = map.centre(at_mean);
        const auto where_max = map.centre(at_max);
        const std::string second = map.cylinder ? "deg" : "m";
        const char* force = map.cylinder || map.edge_v.squaredNorm() > 0.0 ? "N" : "N/m";
        results.push_back({prefix + "peak_mean_pressure", peak_mean, unit, std::nullopt, ""});
        results.push_back(
            {prefix + "peak_mean_pressure_" + c.name_1, where_mean[0], "m", std::nullopt, ""});
        results.push_back(
            {prefix + "peak_mean_pressure_" + c.name_2, where_mean[1], second, std::nullopt, ""});
        results.push_back({prefix + "peak_max_pressure", map.window_seen ? peak_max : std::nan(""),
                           unit, std::nullopt, ""});
        results.push_back(
            {prefix + "peak_max_pressure_" + c.name_1, where_max[0], "m", std::nullopt, ""});
        results.push_back(
            {prefix + "peak_max_pressure_" + c.name_2, where_max[1], second, std::nullopt, ""});
        results.push_back({prefix + "normal_force", total[0], force, std::nullopt, ""});
        results.push_back({prefix + c.traction_1 + "_force", total[1], force, std::nullopt, ""});
        results.push_back({prefix + c.traction_2 + "_force", total[2], force, std::nullopt, ""});
    }
}

} // namespace grainload::particles
