#include "support/case_runner.hpp"
#include "support/csv_rows.hpp"
#include "support/hopper_beverloo.hpp"

#include <cmath>
#include <iostream>
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

/// The first output time at which `level` of the initial mass has left, after the opening.
double time_to_discharge(const std::vector<std::pair<double, double>>& rows, double initial,
                         double level) {
    for (const auto& [time, mass] : rows) {
        if (mass >= level * initial) {
            return time - kOpening;
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

} // namespace
} // namespace grainload::testing
