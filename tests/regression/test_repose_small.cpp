#include "support/case_runner.hpp"
#include "support/frame_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>
#include <iostream>
#include <map>
#include <numbers>
#include <vector>
#include <vtkDataArray.h>
#include <vtkPointData.h>

namespace {

using namespace grainload::testing;

std::string frame_file(const std::string& out, int k) {
    char name[64];
    std::snprintf(name, sizeof name, "/frames/repose_small_%06d.vtm", k);
    return out + name;
}

/// Sum of v^2 / 2 over the sand's particles: the kinetic energy per particle mass (all
/// particles have the same mass).
double kinetic_energy(vtkPolyData* sand) {
    vtkDataArray* velocity = sand->GetPointData()->GetArray("velocity");
    double sum = 0.0;
    for (vtkIdType i = 0; i < sand->GetNumberOfPoints(); ++i) {
        const double* v = velocity->GetTuple3(i);
        sum += 0.5 * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
    return sum;
}

struct Heap {
    double height = 0.0;    ///< top particle centre above the bottom layer's, m
    double slope_deg = 0.0; ///< flank slope between 20 % and 80 % of the height
    double lowest = 0.0;    ///< lowest particle centre, m
    double farthest = 0.0;  ///< largest distance from the axis, m
    double outer_deg = 0.0; ///< atan(height / radius holding 99 % of the particles)
};

/// The heap's free surface: the highest particle centre in every ring of one spacing about
/// the tube's axis; the flank slope is the least-squares slope of those tops over the rings
/// outside the summit whose height lies between 20 % and 80 % of the heap's; the outer angle
/// is atan(H / R99), R99 the radius holding 99 % of the particles (as cases/repose/analyse.py).
Heap measure_heap(vtkPolyData* sand, double spacing) {
    std::map<int, double> top;
    std::vector<double> radii;
    Heap heap;
    heap.lowest = 1e9;
    for (vtkIdType i = 0; i < sand->GetNumberOfPoints(); ++i) {
        double x[3];
        sand->GetPoint(i, x);
        heap.lowest = std::min(heap.lowest, x[2]);
        const double r = std::hypot(x[0], x[1]);
        heap.farthest = std::max(heap.farthest, r);
        radii.push_back(r);
        const int ring = static_cast<int>(r / spacing);
        top[ring] = top.contains(ring) ? std::max(top[ring], x[2]) : x[2];
    }
    int summit = top.begin()->first;
    for (auto& [ring, z] : top) {
        z -= heap.lowest;
        if (z > heap.height) {
            heap.height = z;
            summit = ring;
        }
    }
    double n = 0.0, sr = 0.0, sz = 0.0, srr = 0.0, srz = 0.0;
    for (const auto& [ring, z] : top) {
        if (ring > summit && z >= 0.2 * heap.height && z <= 0.8 * heap.height) {
            const double r = (ring + 0.5) * spacing;
            n += 1.0;
            sr += r;
            sz += z;
            srr += r * r;
            srz += r * z;
        }
    }
    const double slope = (n * srz - sr * sz) / (n * srr - sr * sr);
    heap.slope_deg = std::atan(-slope) * 180.0 / std::numbers::pi;
    const auto r99 =
        radii.begin() + static_cast<std::ptrdiff_t>(0.99 * static_cast<double>(radii.size() - 1));
    std::nth_element(radii.begin(), r99, radii.end());
    heap.outer_deg = std::atan(heap.height / *r99) * 180.0 / std::numbers::pi;
    return heap;
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
