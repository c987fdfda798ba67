#include "support/case_runner.hpp"
#include "support/frame_reader.hpp"
#include "support/gold_summary.hpp"

#include <cmath>
#include <filesystem>
#include <string>

namespace grainload::testing {
namespace {

// cases/column_collapse_2d/column_collapse_2d_half.toml: the right half of a column collapsing
// both ways, with a symmetry plane at x = 0 (ghost particles, docs/theory/sph.md).
constexpr const char* kCase = "cases/column_collapse_2d/column_collapse_2d_half.toml";
// 20 x 10 particles of 2040 kg/m^3 x (10 mm)^2 under 9.81 m/s^2, per metre of depth.
constexpr double kWeight = 200 * 2040.0 * 1e-4 * 9.81;
// At rest at 0.6 s the floor carries the half's weight: the plane carries none of it (a mirror
// image pushes only along its own displacement from the particle, and the vertical parts of the
// pushes of a symmetric pair cancel only in the full model's internal forces). The heap still
// creeps (kinetic energy 1e-6 J), well under the 0.5 % allowed here.
constexpr double kWeightTolerance = 5e-3;
// The energy books close to the bound the CI cases keep (test_column_collapse_small: 1 %):
// the plane does no work on a symmetric motion, so the ledger has nothing to book for it.
constexpr double kEnergyBooks = 0.01;

TEST(SymmetryHalf, RunsFromTheCliCarriesItsWeightAndClosesItsBooks) {
    const CaseRun run = run_case_file(kCase, "symmetry_half");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_NEAR(-result_value(summary, "wall_floor_force_y") / kWeight, 1.0, kWeightTolerance);
    EXPECT_LT(std::abs(result_value(summary, "energy_balance_error")), kEnergyBooks);
    EXPECT_NE(summary.find("\"symmetry x\": \"mirror plane x = 0 m, material on the + side\""),
              std::string::npos)
        << summary;
    // The frames hold the 200 particles of the half, no ghost.
    const auto column =
        read_named_block(frame_path(run.out, "column_collapse_2d_half", 12), "column");
    ASSERT_TRUE(column);
    EXPECT_EQ(column->GetNumberOfPoints(), 200);
    expect_matches_gold(run.out, "cases/column_collapse_2d/column_collapse_2d_half.toml");
}

// Ghosts are not checkpointed: the restart selects them again from the positions of the
// neighbour list's last build, so the continued run ends bit for bit where the whole run does.
TEST(SymmetryHalf, RestartReproducesTheUninterruptedRun) {
    const std::string base = test_folder("symmetry_restart");
    ASSERT_EQ(run_whole_and_split(kCase, base, "0.15 s", "0.3 s"), "");
    const std::string frame = "/frames/column_collapse_2d_half_000006/column.vtp";
    const std::string whole = read_file(base + "_whole" + frame);
    ASSERT_GT(whole.size(), 1000u);
    EXPECT_TRUE(whole == read_file(base + "_split" + frame)) << "the column's frame at 0.3 s";
    const std::string a = read_file(base + "_whole/summary.json");
    const std::string b = read_file(base + "_split/summary.json");
    for (const char* figure :
         {"kinetic_energy", "energy_balance_error", "wall_floor_force_x", "wall_floor_force_y"}) {
        EXPECT_EQ(result_value(a, figure), result_value(b, figure)) << figure;
    }
}

// cases/sand_on_plate/sand_on_plate_quarter.toml against sand_on_plate_small.toml: a coupled
// plate cut by two planes, the shell with symmetry conditions, its SPH wall mirrored. The
// quarter computes the same sums as the full model in another order, so the figures agree to
// round-off (measured: centre deflection and energy books equal to all 12 printed digits, the
// plate's load x 4 to 4e-12). 1e-9 relative leaves room for other compilers' rounding.
constexpr double kQuarterRoundOff = 1e-9;

TEST(SymmetryHalf, QuarterOfACoupledPlateSagsAndCarriesAsTheFullPlate) {
    const CaseRun full =
        run_case_file("cases/sand_on_plate/sand_on_plate_small.toml", "symmetry_full_plate");
    ASSERT_EQ(full.cli.exit_code, 0) << full.cli.output;
    const CaseRun quarter =
        run_case_file("cases/sand_on_plate/sand_on_plate_quarter.toml", "symmetry_quarter_plate");
    ASSERT_EQ(quarter.cli.exit_code, 0) << quarter.cli.output;
    const std::string a = read_file(full.out + "/summary.json");
    const std::string b = read_file(quarter.out + "/summary.json");
    const double deflection = result_value(a, "centre_deflection");
    EXPECT_LT(deflection, -1e-3); // the plate sags by about a millimetre
    EXPECT_NEAR(result_value(b, "centre_deflection") / deflection, 1.0, kQuarterRoundOff);
    EXPECT_NEAR(4.0 * result_value(b, "wall_plate_force_z") / result_value(a, "wall_plate_force_z"),
                1.0, kQuarterRoundOff);
    // The side walls' small vertical force (0.19 N, from the lattice of their particles) is a
    // difference of larger terms: the full model's own walls x0 and x1 differ by 1e-8 of it.
    constexpr double kSideWallRoundOff = 1e-7;
    EXPECT_NEAR(2.0 * result_value(b, "wall_x1_force_z") / result_value(a, "wall_x1_force_z"), 1.0,
                kSideWallRoundOff);
    EXPECT_NEAR(result_value(b, "energy_balance_error"), result_value(a, "energy_balance_error"),
                kQuarterRoundOff);
    expect_matches_gold(full.out, "cases/sand_on_plate/sand_on_plate_small.toml");
    expect_matches_gold(quarter.out, "cases/sand_on_plate/sand_on_plate_quarter.toml");
}

} // namespace
} // namespace grainload::testing
