#include "support/case_runner.hpp"
#include "support/frame_reader.hpp"
#include "support/heap_profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>
#include <iostream>
#include <vector>

namespace {

using namespace grainload::testing;

std::string frame_file(const std::string& out, int k) {
    char name[64];
    std::snprintf(name, sizeof name, "/frames/repose_small_%06d.vtm", k);
    return out + name;
}

// The CI version of the repose case: a cylinder of cohesionless sand (phi = 30 deg, 416
// particles) in a frictionless tube on a rough floor (mu = 1); the tube is lifted and the
// sand forms a heap. Checks against physics, not against a stored run:
// - every particle is kept, above the floor's surface and on it (the contact holds);
// - the heap comes to rest: the kinetic energy at the end is below 1e-4 of its peak during
//   the flow (a heap still creeping or bouncing on the contact would not get there);
// - the sand has flowed out of the tube: the heap is lower than the settled column and
//   reaches beyond the tube's radius;
// - the heap is no steeper than phi: a cohesionless slope cannot stand steeper than its
//   friction angle (infinite-slope limit). The flank fit may exceed it by 5 deg (the tops of
//   20 mm rings are read to +-half a spacing over a flank of about 5 rings); the outer angle
//   atan(H / R99), which averages over the whole heap, must stay below phi itself. And the
//   outer angle is above phi / 2: a heap, not a flood spreading over the floor (measured with
//   the compression cone: 22.0 deg here, 26.9 deg at 10 mm in repose.toml, whose flank fit
//   reads 30.3 deg; the coarse flank fit here reads 20.3 deg, too noisy at 3-4 particles of
//   height for a tighter bound);
// - the floor carries the sand's weight, N m g (summary.json's final wall force), to 1 %: once
//   the heap is at rest and the tube clear of it nothing else holds the sand up (the contact
//   and friction reactions are spread onto the wall's particles, so this also checks that
//   they are the reactions of what the sand feels).
TEST(ReposeSmall, LiftedTubeLeavesAHeapAtRestNoSteeperThanTheFrictionAngle) {
    const CaseRun run = run_case_file("cases/repose/repose_small.toml", "repose_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string& out = run.out;
    const double spacing = 0.02, phi = 30.0, tube_radius = 0.132, floor_half_width = 0.24;
    const double tube_moves = 0.1, interval = 0.05; // s, from the case file

    std::vector<double> kinetic;
    int last = 0;
    for (int k = 0; std::filesystem::exists(frame_file(out, k)); ++k) {
        kinetic.push_back(kinetic_energy(read_particle_block(frame_file(out, k))));
        last = k;
    }
    ASSERT_GT(last, 30);
    const auto first = read_particle_block(frame_file(out, 0));
    const auto sand = read_particle_block(frame_file(out, last));
    ASSERT_EQ(sand->GetNumberOfPoints(), first->GetNumberOfPoints());

    const auto lift = static_cast<std::size_t>(tube_moves / interval);
    const double peak = *std::max_element(kinetic.begin() + lift, kinetic.end());
    const Heap column = measure_heap(first, spacing);
    const Heap heap = measure_heap(sand, spacing);
    std::cout << "heap height " << heap.height * 1e3 << " mm (column " << column.height * 1e3
              << " mm), reach " << heap.farthest * 1e3 << " mm, slope " << heap.slope_deg
              << " deg, outer angle " << heap.outer_deg << " deg (phi " << phi
              << " deg), kinetic energy at the end / peak " << kinetic.back() / peak << "\n";

    const std::string summary = read_file(out + "/summary.json");
    const std::string key = "\"wall_floor_force_z\": {\"value\": ";
    const auto at = summary.find(key);
    ASSERT_NE(at, std::string::npos) << summary;
    const double floor_force = std::strtod(summary.c_str() + at + key.size(), nullptr);
    const double weight =
        static_cast<double>(sand->GetNumberOfPoints()) * 1600.0 * std::pow(spacing, 3) * 9.81;
    std::cout << "floor force " << floor_force << " N, weight " << weight << " N\n";
    EXPECT_NEAR(-floor_force, weight, 0.01 * weight);

    EXPECT_GT(heap.lowest, 0.0);
    EXPECT_LT(heap.farthest, floor_half_width);
    EXPECT_LT(kinetic.back(), 1e-4 * peak);
    EXPECT_LT(heap.height, column.height);
    EXPECT_GT(heap.farthest, tube_radius);
    EXPECT_LT(heap.slope_deg, phi + 5.0);
    EXPECT_LT(heap.outer_deg, phi);
    EXPECT_GT(heap.outer_deg, 0.5 * phi);
}

} // namespace
