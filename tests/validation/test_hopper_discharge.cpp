#include "support/case_runner.hpp"
#include "support/csv_rows.hpp"
#include "support/hopper_beverloo.hpp"

#include <cmath>
#include <iostream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace grainload::testing {
namespace {

// The plane-wedge hopper of D. Markauskas, "Discrete element modelling of complex
// axisymmetrical particle flow", in plane strain at 25 mm, rigid walls, the
// gate removed at once at 0.4 s: cases/hopper_discharge/hopper_discharge.toml, figures in
// docs/validation/hopper_discharge.md ("Results"). About 20 s on 2 threads.
constexpr double kOpening = 0.4; // s, the gate's remove_at

/// The first output time at which `level` of the initial mass has left, after the opening at
/// `opening`.
double time_to_discharge(const std::vector<std::pair<double, double>>& rows, double initial,
                         double level, double opening = kOpening) {
    for (const auto& [time, mass] : rows) {
        if (mass >= level * initial) {
            return time - opening;
        }
    }
    return std::nan("");
}

// - Emptying time against the experiment: the paper's hopper is empty about 1.8 s after the
//   orifice opens. Read as the time 99 % is out (discharge.csv, every 0.05 s, as
//   cases/hopper_discharge/analyse.py): measured 1.80 s. Tolerance 0.15 s: the paper's "about
//   1.8 s" read to its last digit (+-0.05 s), one output interval (0.05 s), and the slow run-off
//   of the last per cent from the plates (the paper's own deposition sequence,
//   hopper_deposition.toml, empties in 1.83 s).
// - Steady rate against Beverloo's slot law with k = 1.5, W/L = C' rho_b sqrt(g) (B - k d)^1.5
//   = 161 kg/m/s (C' = 1.03): the page documents the gap, 244 kg/m/s = 1.52 times the law at
//   this spacing (the rate grows with resolution: the walls' contact layers narrow the orifice
//   by about 3.7 spacings; at 25 mm that matches the spheres' empty annulus k d, which is why
//   the emptying time agrees). Asserted as documented: 1.44-1.60 times the law, the measured
//   ratio with 5 %, the trade table's budget, within which this spacing's stiffness and CFL
//   move it (+4.1 % at most) and round-off does not.
// - Books: mass audit to the round-off of about 2000 particle masses, energy within 0.3 %
//   (measured 1.3e-4).
TEST(HopperDischargeValidation, EmptiesInTheExperimentsTimeAt25mm) {
    const CaseRun run =
        run_case_file("cases/hopper_discharge/hopper_discharge.toml", "hopper_discharge");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const HopperDischarge discharge =
        read_hopper_discharge(read_file(run.out + "/summary.json"), 2000);
    const double emptied = time_to_discharge(discharge_rows(run.out), discharge.initial_mass, 0.99);
    const double rate = discharge.steady_rate;
    const double beverloo = beverloo_slot(1.5);
    std::cout << "hopper discharge (25 mm): 99 % out " << emptied << " s after opening; steady "
              << "rate " << rate << " kg/m/s, " << rate / beverloo << " x Beverloo (k = 1.5, "
              << beverloo << " kg/m/s)\n";
    EXPECT_NEAR(emptied, 1.8, 0.15);
    EXPECT_GT(rate / beverloo, 1.44);
    EXPECT_LT(rate / beverloo, 1.60);
}

/// A DEM hopper run's mass and its 99 % time after the gate left at 2.5 s; the mass audit to
/// the round-off of its 2000 sphere masses.
std::pair<double, double> dem_hopper(const std::string& case_file, const std::string& name) {
    const CaseRun run = run_case_file(case_file, name);
    EXPECT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    const double initial = result_value(summary, "initial_mass");
    EXPECT_LT(std::abs(result_value(summary, "mass_audit_error")), 2000 * 2.2e-16);
    return {initial, time_to_discharge(discharge_rows(run.out), initial, 0.99, 2.5)};
}

// The same hopper in 3D with the paper's own DEM and both its fills: 2000 spheres of radius
// 0.03-0.035 m, and 1000 particles of two touching spheres of those radii, with its contact
// parameters (cases/hopper_discharge/hopper_discharge_dem*.toml, the gate leaving at 2.5 s
// once the fill rests). About 2 minutes on 2 threads.
// - Emptying times against the paper's, "empty after 1.8 s" (spheres) and 2.4 s (pairs), read
//   as the time 99 % is out (discharge.csv every 0.05 s, the sink one grain diameter below the
//   orifice): measured 2.00 s and 2.65 s (another packing seed: 2.05 s for the spheres). Bound
//   +- 0.35 s: the paper's reading (+-0.05 s), the output interval, the packing's seed, and
//   what the paper leaves unstated of its hopper (its height and the walls closing its depth,
//   here smooth planes with the grains' friction), which slows both fills alike.
// - Their ratio, the shape's effect the paper measures: 2.4 / 1.8 = 1.33 there, measured 1.33;
//   bound +- 0.1 (two output intervals over 2 s).
// - Mass: 2000 spheres of the radius distribution weigh 2000 (4/3) pi <r^3> rho = 144.6 kg;
//   within 1 % (the sample mean of 2000 draws: 0.3 % standard error).
TEST(HopperDischargeValidation, DemSpheresAndPairsEmptyNearThePapersTimes) {
    const auto [spheres_mass, spheres] =
        dem_hopper("cases/hopper_discharge/hopper_discharge_dem.toml", "hopper_discharge_dem");
    const auto [pairs_mass, pairs] = dem_hopper(
        "cases/hopper_discharge/hopper_discharge_dem_pairs.toml", "hopper_discharge_dem_pairs");
    std::cout << "DEM hopper: spheres " << spheres_mass << " kg, 99 % out " << spheres
              << " s after opening (the paper: empty after 1.8 s); pairs " << pairs_mass << " kg, "
              << pairs << " s (2.4 s); ratio " << pairs / spheres << " (1.33)\n";
    const double mean_cube = (std::pow(0.035, 4) - std::pow(0.03, 4)) / (4.0 * 0.005);
    const double expected = 2000.0 * 4.0 / 3.0 * std::numbers::pi * mean_cube * 500.0;
    EXPECT_NEAR(spheres_mass, expected, 0.01 * expected);
    EXPECT_NEAR(pairs_mass, expected, 0.01 * expected);
    EXPECT_NEAR(spheres, 1.8, 0.35);
    EXPECT_NEAR(pairs, 2.4, 0.35);
    EXPECT_NEAR(pairs / spheres, 2.4 / 1.8, 0.1);
}

} // namespace
} // namespace grainload::testing
