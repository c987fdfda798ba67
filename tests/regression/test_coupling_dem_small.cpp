// Glass beads on an elastic plate, run from the command line: the DEM's grains settle on a
// coupled, simply supported steel plate inside four frictionless walls. The plate carries the
// weight, the exchange keeps its momentum books, and the plate sags as under a uniform load.
// Killed and restarted while the beads land, the run writes what the uninterrupted run writes.

#include "support/case_runner.hpp"
#include "support/gold_summary.hpp"
#include "support/interrupted_run.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>

namespace {

using namespace grainload::testing;

constexpr const char* kCase = "cases/sand_on_plate/grains_on_plate_small.toml";
constexpr double kWindow = 0.025;   // the case's coupling window
constexpr double kRelaxation = 0.5; // its relaxation (the default)

// - Static equilibrium: the plate carries the settled beads' weight (the interface load and the
//   supports' reactions; measured 1.3e-5 and 9e-5 at 0.8 s, where what still moves changes the load
//   by its momentum's rate; bound 1e-3); the frictionless walls carry none of it (exactly 0).
// - The exchange's books: window by window the shell's load moves towards the beads' mean load
//   by the relaxation omega, so over equal windows the beads' impulse on the plate exceeds the
//   shell's by the window times the final load over omega (bound 1e-9 of it: round-off of
//   32 windows of sums).
// - The sag: w = 0.00406 q a^4 / D under q = W / a^2 (Timoshenko & Woinowsky-Krieger, table 8).
//   Bound 10 %: a random packing puts its weight on the plate through about 500 contacts whose
//   forces scatter as much as their mean (Mueth, Jaeger & Nagel 1998), and the centre's
//   deflection weighs the hundred or so nearest it: 1/sqrt(100) = 10 % (measured +1.9 %);
//   the 8 x 8 MITC4 mesh is 0.3 % stiff (the SPH layer on the same plate).
// On one thread and with the BLAS kernels the tests pin (tests/support/cli_runner.hpp), as its
// gold file was written: the shell's sparse solver sums in blocks per thread and in the
// kernels' own order, and a packing of grains amplifies a change in the last bit as any
// granular packing does (0.1 % in the beads' centre of mass after 0.8 s on two threads; 0.3 %
// between the kernel sets OpenBLAS picked on two machines).
TEST(CouplingDemSmall, BeadsOnAPlateWeighOnItAndBendItLikeAUniformLoad) {
    const CaseRun run = run_case_file(kCase, "grains_on_plate_small", "--threads 1");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_EQ(result_value(summary, "grains"), 1000.0);
    // The beads' weight, sum m g, as the DEM reports it beside its walls' load.
    const double weight = figure_reference(summary, "walls_load_along_gravity").reference;
    const double load = -result_value(summary, "interface_force_z");
    EXPECT_NEAR(load, weight, 1e-3 * weight);
    EXPECT_NEAR(result_value(summary, "support_reaction_z"), weight, 1e-3 * weight);
    for (const char* wall : {"x0", "x1", "y0", "y1"}) {
        EXPECT_EQ(result_value(summary, std::string("wall_") + wall + "_force_z"), 0.0) << wall;
    }
    const double lag =
        result_value(summary, "interface_impulse_z") - result_value(summary, "shell_impulse_z");
    const double expected_lag = -kWindow * load / kRelaxation;
    EXPECT_NEAR(lag, expected_lag, 1e-9 * std::abs(expected_lag));
    const double d = 210e9 * 0.002 * 0.002 * 0.002 / (12.0 * (1.0 - 0.09));
    const double navier = -0.00406 * (weight / (0.4 * 0.4)) * std::pow(0.4, 4) / d;
    const double w = result_value(summary, "centre_deflection");
    std::cout << "beads on plate: load " << load << " N (weight " << weight << " N), centre " << w
              << " m (plate under q: " << navier << " m)\n";
    EXPECT_NEAR(w, navier, 0.1 * std::abs(navier));
    expect_matches_gold(run.out, kCase);
}

// The paper's DEM hopper with both sheets as coupled shells (hopper_shell_dem.toml), filled and
// at rest before its gate goes (2.45 s): two interfaces on the element sets of one Gmsh part.
//  - Static equilibrium: the sheets, the gate and the end plates carry the spheres' weight
//    (measured 2.6e-3 at 2.45 s, where the fill still creeps; bound 1e-2).
//  - The shell's load is the sheets' wall forces, lagged a window and relaxed: at rest they
//    agree (measured 7.8e-4 of the weight; bound 1e-2).
//  - The grains' friction puts moments on the sheets' nodes about an axis the deformed
//    triangles lean off the director by; the moments' component about the director is taken
//    out (a shell resists it by its drilling spring only): with it the static shell's Newton
//    iterations stalled at 0.475 s and the run stopped with exit 3.
TEST(CouplingDemSmall, TheHoppersSheetsCarryTheFillAtRest) {
    const CaseRun run = run_case_file("cases/hopper_discharge/hopper_shell_dem.toml",
                                      "hopper_shell_dem", "--set 'case.end_time=2.45 s'");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    const double weight = result_value(summary, "initial_mass") * 9.81;
    double walls = 0.0;
    for (const char* wall : {"left", "right", "gate", "front", "back"}) {
        walls -= result_value(summary, std::string("wall_") + wall + "_force_z");
    }
    EXPECT_NEAR(walls, weight, 1e-2 * weight);
    const double sheets =
        -result_value(summary, "wall_left_force_z") - result_value(summary, "wall_right_force_z");
    EXPECT_NEAR(-result_value(summary, "interface_force_z"), sheets, 1e-2 * weight);
}

// SIGKILL at random moments while the beads land on the plate, and a restart: the walls'
// vertices, the window's impulses and the shell's load come back from the checkpoint, so every
// output equals the uninterrupted run's.
TEST(CouplingDemSmall, KilledAndRestartedWhileTheBeadsLandReproducesTheRun) {
    const std::vector<std::string> arguments = {
        "run", source_path(kCase), "--set", "case.end_time=0.2 s", "--threads", "1"};
    expect_restarts_reproduce_the_run(arguments, "grains_on_plate", 2);
}

} // namespace
