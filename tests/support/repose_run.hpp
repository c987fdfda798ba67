#pragma once
// A run of a repose case (cases/repose/): the heap it left, its kinetic energy, its floor load.

#include "support/cli_runner.hpp"
#include "support/frame_reader.hpp"
#include "support/heap_profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace grainload::testing {

/// What the repose tests assert, read from the frames and summary.json of a run: the sand is
/// 1600 kg/m^3 in cubes of one spacing under 9.81 m/s^2 and the tube is lifted after 0.1 s,
/// output every 0.05 s (both case files).
struct ReposeRun {
    int last_frame = 0;
    long first_particles = 0;   ///< particles in the first frame
    long last_particles = 0;    ///< and in the last
    Heap column;                ///< the settled column, first frame
    Heap heap;                  ///< the heap, last frame
    double final_kinetic = 0.0; ///< kinetic energy per particle mass in the last frame
    double peak_kinetic = 0.0;  ///< its largest value once the tube moves
    double floor_force = 0.0;   ///< N, the floor's final z force (summary.json)
    double weight = 0.0;        ///< N, last_particles x m x g
};

inline ReposeRun read_repose_run(const std::string& out, const std::string& name, double spacing) {
    constexpr double kTubeMoves = 0.1; // s
    constexpr double kInterval = 0.05; // s
    ReposeRun run;
    std::vector<double> kinetic;
    for (int k = 0; std::filesystem::exists(frame_path(out, name, k)); ++k) {
        kinetic.push_back(kinetic_energy(read_particle_block(frame_path(out, name, k))));
        run.last_frame = k;
    }
    if (kinetic.empty()) {
        return run;
    }
    const auto first = read_particle_block(frame_path(out, name, 0));
    const auto sand = read_particle_block(frame_path(out, name, run.last_frame));
    run.first_particles = first->GetNumberOfPoints();
    run.last_particles = sand->GetNumberOfPoints();
    run.column = measure_heap(first, spacing);
    run.heap = measure_heap(sand, spacing);
    const auto lift =
        std::min(kinetic.size() - 1, static_cast<std::size_t>(kTubeMoves / kInterval));
    run.peak_kinetic = *std::max_element(kinetic.begin() + static_cast<long>(lift), kinetic.end());
    run.final_kinetic = kinetic.back();

    const std::string summary = read_file(out + "/summary.json");
    const std::string key = "\"wall_floor_force_z\": {\"value\": ";
    const auto at = summary.find(key);
    run.floor_force = at == std::string::npos
                          ? std::nan("")
                          : std::strtod(summary.c_str() + at + key.size(), nullptr);
    run.weight = static_cast<double>(run.last_particles) * 1600.0 * std::pow(spacing, 3) * 9.81;
    std::cout << name << ": heap height " << run.heap.height * 1e3 << " mm (column "
              << run.column.height * 1e3 << " mm), reach " << run.heap.farthest * 1e3
              << " mm, slope " << run.heap.slope_deg << " deg, outer angle " << run.heap.outer_deg
              << " deg, kinetic energy at the end / peak " << run.final_kinetic / run.peak_kinetic
              << ", floor force " << run.floor_force << " N, weight " << run.weight << " N\n";
    return run;
}

} // namespace grainload::testing
