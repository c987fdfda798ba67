#include "support/case_runner.hpp"
#include "support/gold_summary.hpp"
#include "support/repose_run.hpp"

#include <gtest/gtest.h>

namespace {

using namespace grainload::testing;

// The CI version of the repose case: a cylinder of cohesionless sand (phi = 30 deg, 416
// particles) in a frictionless tube on a rough floor (mu = 1); the tube is lifted and the
// sand forms a heap. Checks against physics, then against the case's gold file:
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
//   they are the reactions of what the sand feels);
// - every figure of summary.json where cases/repose/gold/repose_small.json has it.
TEST(ReposeSmall, LiftedTubeLeavesAHeapAtRestNoSteeperThanTheFrictionAngle) {
    const CaseRun run = run_case_file("cases/repose/repose_small.toml", "repose_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const double spacing = 0.02, phi = 30.0, tube_radius = 0.132, floor_half_width = 0.24;
    const ReposeRun repose = read_repose_run(run.out, "repose_small", spacing);
    ASSERT_GT(repose.last_frame, 30);
    ASSERT_EQ(repose.last_particles, repose.first_particles);
    EXPECT_NEAR(-repose.floor_force, repose.weight, 0.01 * repose.weight);

    const Heap& heap = repose.heap;
    EXPECT_GT(heap.lowest, 0.0);
    EXPECT_LT(heap.farthest, floor_half_width);
    EXPECT_LT(repose.final_kinetic, 1e-4 * repose.peak_kinetic);
    EXPECT_LT(heap.height, repose.column.height);
    EXPECT_GT(heap.farthest, tube_radius);
    EXPECT_LT(heap.slope_deg, phi + 5.0);
    EXPECT_LT(heap.outer_deg, phi);
    EXPECT_GT(heap.outer_deg, 0.5 * phi);
    expect_matches_gold(run.out, "cases/repose/repose_small.toml");
}

} // namespace
