#include "support/case_runner.hpp"
#include "support/coupling_figures.hpp"
#include "support/frame_reader.hpp"
#include "support/gold_summary.hpp"

#include <algorithm>
#include <limits>
#include <vtkDataSet.h>

namespace grainload::testing {
namespace {

constexpr double kGravity = 9.81;
// The plate's mean load against the held block's weight: the frictionless side walls'
// corrugation carries up to 0.3 % of a block's weight (test_coupling_small.cpp), the soft
// block's sloshing moves a mean over 0.2 s by 0.2 %.
constexpr double kMeanLoadTolerance = 5e-3;
// The same at one instant: the held block, free on the side the other block left, sloshes on
// the plate with about 1 % of its weight at 0.5 s.
constexpr double kInstantTolerance = 2e-2;

/// Lowest and highest particle centre (z) of a body block of a frame.
std::pair<double, double> z_range(const std::string& vtm, const std::string& body) {
    const auto block = read_named_block(vtm, body);
    std::pair<double, double> range{std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity()};
    if (block == nullptr || block->GetNumberOfPoints() == 0) {
        ADD_FAILURE() << "no block " << body << " in " << vtm;
        return range;
    }
    for (vtkIdType k = 0; k < block->GetNumberOfPoints(); ++k) {
        const double z = block->GetPoint(k)[2];
        range.first = std::min(range.first, z);
        range.second = std::max(range.second, z);
    }
    return range;
}

// Two blocks of the soft sand of sand_on_plate_small.toml side by side over one coupled plate
// whose interface lists only "held" (`bodies`): cases/sand_on_plate/two_bodies_one_plate_small
// .toml. Conservation says the plate carries the held block's weight M_h g and none of the
// other's (a plate that met both blocks would carry M_h g + M_p g, 1.9 times as much):
//  - the mean interface load over 0.3-0.5 s (coupling.csv, as test_coupling_small.cpp) equals
//    M_h g within kMeanLoadTolerance (measured +0.17 %);
//  - so do the static shell's support reactions at 0.5 s within kInstantTolerance (measured
//    -0.7 %);
//  - the passing block ends wholly below the plate (it fell through the plate's wall
//    particles and the shell) and above the floor 250 mm below, which caught it (it still
//    bounces there at 0.5 s: the floor's force is printed, not compared).
TEST(CouplingBodies, APlateActingOnOneBodyCarriesItAloneAndTheOtherFallsThrough) {
    const CaseRun run = run_case_file("cases/sand_on_plate/two_bodies_one_plate_small.toml",
                                      "two_bodies_one_plate_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    const double particle_mass = 1600.0 * 0.02 * 0.02 * 0.02;
    const double held = 10 * 20 * 3 * particle_mass * kGravity;
    const double passing = 9 * 20 * 3 * particle_mass * kGravity;
    double time = 0.0;
    const double load = -mean_shell_load_z(run.out, 0.3, time);
    ASSERT_GT(time, 0.1);
    const double floor = -result_value(summary, "wall_floor_force_z");
    const double sides = -walls_force_z(summary, {"x0", "x1", "y0", "y1"});
    const std::string last = frame_path(run.out, "two_bodies_one_plate_small", 5);
    const auto [held_low, held_high] = z_range(last, "held");
    const auto [passing_low, passing_high] = z_range(last, "passing");
    std::cout << "two bodies, one plate: mean plate load " << load << " N (held block " << held
              << " N, passing " << passing << " N), floor " << floor << " N, side walls " << sides
              << " N; held z " << held_low << ".." << held_high << " m, passing z " << passing_low
              << ".." << passing_high << " m\n";
    EXPECT_NEAR(load, held, kMeanLoadTolerance * held);
    EXPECT_NEAR(result_value(summary, "support_reaction_z"), held, kInstantTolerance * held);
    // ... and the run says so itself: the case's [[case.reference]] gives the supports the held
    // block's weight (75.341 N, the printed digits of M_h g), and summary.json carries it with
    // the relative error, within the same instant's tolerance.
    const FigureReference supports = figure_reference(summary, "support_reaction_z");
    EXPECT_NEAR(supports.reference, held, 1e-5 * held);
    EXPECT_NE(supports.source.find("the held block's weight"), std::string::npos);
    EXPECT_LT(supports.relative_error, kInstantTolerance);
    EXPECT_GT(held_low, 0.0);
    EXPECT_LT(passing_high, 0.0);
    EXPECT_GT(passing_low, -0.25);
    expect_matches_gold(run.out, "cases/sand_on_plate/two_bodies_one_plate_small.toml");
}

} // namespace
} // namespace grainload::testing
