// A DEM triaxial test run from the command line as a user runs it: 300 grains consolidated
// isotropically by servo walls and sheared at a constant rate. The servos hold the confining
// stress, the sample stays in equilibrium, a dense packing dilates and softens after its peak,
// and a run killed and restarted while the walls move writes what the uninterrupted run writes.

#include "support/case_runner.hpp"
#include "support/gold_summary.hpp"
#include "support/interrupted_run.hpp"

#include <gtest/gtest.h>

namespace {

using namespace grainload::testing;

constexpr const char* kCase = "cases/triaxial/triaxial_dem_small.toml";

// At 10 % axial strain, means over the last 1 ms:
// - the side walls' stress against the confining 100 kPa: measured 1.6e-3 above it (the servo
//   corrects a step's error in the next; the walls follow a dilating sample outwards), bound
//   5e-3;
// - the base's stress against the platen's: measured 4e-4, bound 5e-3 (quasi-static shear at an
//   inertial number of 6e-4: what the grains' momentum changes carries is below that);
// - a packing consolidated frictionless is dense: it contracts, then dilates past its start
//   (Reynolds' dilatancy; measured -2.1 % at 10 %, bound < -0.5 %), and its friction angle
//   peaks and falls to a lower value (measured 21.3 deg at 1.5 % and 19.1 deg at 10 %: peak
//   at least 1 deg above the last);
// - the mobilised angle at 10 % lies within 15-30 deg, the range of the critical-state angles of
//   sphere packings of inter-grain friction 0.3-0.5 in DEM (Thornton 2000, Geotechnique 50;
//   the thesis' 2D disks at friction 0.45 carry 0.225 MPa at 0.1 MPa, 22.6 deg).
TEST(TriaxialDemSmall, ServosHoldTheConfinementWhileADenseSampleDilatesAndSoftens) {
    const CaseRun run = run_case_file(kCase, "triaxial_dem_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    const FigureReference side = figure_reference(summary, "triaxial_side_stress");
    EXPECT_LT(side.relative_error, 5e-3) << side.value << " Pa against " << side.reference;
    const FigureReference base = figure_reference(summary, "triaxial_base_stress");
    EXPECT_LT(base.relative_error, 5e-3) << base.value << " Pa against " << base.reference;
    EXPECT_NEAR(result_value(summary, "triaxial_axial_strain"), 0.1, 1e-9);
    EXPECT_LT(result_value(summary, "triaxial_volumetric_strain"), -0.005);
    const double last = result_value(summary, "triaxial_friction_angle");
    EXPECT_GT(result_value(summary, "triaxial_peak_friction_angle"), last + 1.0);
    EXPECT_GT(last, 15.0);
    EXPECT_LT(last, 30.0);
    expect_matches_gold(run.out, kCase);
}

// SIGKILL at random moments after the first checkpoint and a restart, across the start of the
// shear (consolidation to 2 ms, then the platen moves): frames, triaxial.csv, wall_forces.csv,
// log and summary equal the uninterrupted run's (the servos' places and speeds, the cell's
// sums and its shear reference restored bit for bit).
TEST(TriaxialDemSmall, KilledAndRestartedReproducesTheUninterruptedRun) {
    const std::vector<std::string> arguments = {"run",       source_path(kCase),
                                                "--set",     "case.end_time=4 ms",
                                                "--set",     "case.output_interval=0.25 ms",
                                                "--set",     "dem.triaxial.shear_start=2 ms",
                                                "--threads", "1"};
    expect_restarts_reproduce_the_run(arguments, "triaxial_dem", 2);
}

} // namespace
