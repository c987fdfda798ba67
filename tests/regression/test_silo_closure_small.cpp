#include "support/case_runner.hpp"
#include "support/csv_rows.hpp"
#include "support/frame_reader.hpp"
#include "support/gold_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vtkPoints.h>

namespace grainload::testing {
namespace {

// cases/silo/silo_closure_small.toml: the CI slot silo discharging from 2 s, its outlet shut
// by a slide gate from 2.8 s (stopped at 3.075 s, 65 mm short of the far edge); docs/
// validation/silo.md, "Sudden closure".
constexpr double kDensity = 1500.0; // kg/m^3, the sand's
constexpr double kYoung = 5e6;      // Pa
constexpr double kPoisson = 0.3;
constexpr double kSiloWidth = 0.5; // m
constexpr double kGateTop = -0.05; // m, the gate's surface

// - Closed: nothing leaves once the stream below the gate has cleared (the discharged mass at
//   the end equals that at 3.3 s), and every particle ends above the gate's surface (none
//   pushed through or left inside it; the lowest rests at +3 mm).
// - The books: the gate sweeping the stream is the hardest thing the ledger sees here; 0.95 %
//   measured, 1.3 % at half the CFL factor (the sweep's work itself changes by 13 % with the
//   step), so 2 %.
// - The closure's peak (the largest 20 ms interval mean of the right wall's bottom bins)
//   against two bounds. Arresting a column that moves down at v = W / (rho B) (the steady rate
//   W over the silo's width) raises the vertical stress by at most rho c v, c the P-wave speed
//   of the elastic sand (Joukowsky): the wall's pressure cannot rise by more than that (K <= 1).
//   And the arrest must show: the peak above twice the pressure at rest (measured 5.5-6.5
//   times, 14.5-17.3 kPa at CFL 0.15-0.3, against rest 2.65 kPa and rho c v = 66 kPa).
TEST(SiloClosureSmall, ASlideGateShutsTheOutletAndTheArrestLoadsTheWall) {
    const CaseRun run = run_case_file("cases/silo/silo_closure_small.toml", "silo_closure_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_LT(std::abs(result_value(summary, "mass_audit_error")), 1e-13);
    EXPECT_LT(std::abs(result_value(summary, "energy_balance_error")), 0.02);
    double at_3_3 = -1.0;
    double at_end = -1.0;
    for (const auto& [time, mass] : discharge_rows(run.out)) {
        at_3_3 = std::abs(time - 3.3) < 1e-9 ? mass : at_3_3;
        at_end = mass;
    }
    ASSERT_GT(at_3_3, 0.0);
    EXPECT_EQ(at_end, at_3_3);
    const auto sand = read_named_block(frame_path(run.out, "silo_closure_small", 180), "sand");
    ASSERT_TRUE(sand);
    double lowest = 1e9;
    for (vtkIdType i = 0; i < sand->GetNumberOfPoints(); ++i) {
        lowest = std::min(lowest, sand->GetPoint(i)[1]);
    }
    EXPECT_GT(lowest, kGateTop);

    const auto rest = numeric_csv_rows(run.out + "/wall_maps/rest_window.csv");
    const auto closure = numeric_csv_rows(run.out + "/wall_maps/closure_window.csv");
    ASSERT_EQ(rest.size(), 8u);
    ASSERT_EQ(closure.size(), 8u);
    const double modulus = kYoung * (1.0 - kPoisson) / ((1.0 + kPoisson) * (1.0 - 2.0 * kPoisson));
    const double speed = result_value(summary, "sink_below_steady_rate") / (kDensity * kSiloWidth);
    const double joukowsky = kDensity * std::sqrt(modulus / kDensity) * speed;
    const double peak = std::max(closure[0][5], closure[1][5]);
    const double at_rest = std::max(rest[0][4], rest[1][4]);
    std::printf("closure: peak %.0f Pa, at rest %.0f Pa, rho c v %.0f Pa (v %.3f m/s)\n", peak,
                at_rest, joukowsky, speed);
    EXPECT_GT(peak, 2.0 * at_rest);
    EXPECT_LT(peak, at_rest + joukowsky);
    expect_matches_gold(run.out, "cases/silo/silo_closure_small.toml");
}

} // namespace
} // namespace grainload::testing
