#include "support/case_runner.hpp"
#include "support/silo_rest.hpp"

#include <cmath>
#include <iostream>
#include <string>

namespace grainload::testing {
namespace {

// The slot silo at rest at the case file's resolution (cases/silo/silo_rest.toml, 12.5 mm, 35
// particles across; docs/validation/silo.md, "Full version"): filled by its source to 2 s,
// settled, read at 3.5 s. About 5 min on 2 threads.
constexpr double kSpacing = 0.0125;        // m
constexpr double kParticleMass = 0.234375; // kg/m: 1500 kg/m^3 x (12.5 mm)^2

// The reference is Janssen's p_h for a slot with K bracketed by 1 - sin(phi) = 0.5 and
// EN 1991-4's 1.1 (1 - sin phi) = 0.55, averaged over each band's depths.
// - p_h per band 0.2-1.0 m: the page measures 0.73-0.85 of the bracket's mean (0.76-0.88 of
//   Janssen with K = 0.5), because the continuum's own K, p_h / p_v, is 0.33-0.36, below the
//   bracket: the documented gap. Asserted as the page states it: p_h below Janssen with
//   K = 0.55 (the design bracket stays conservative, by 15-25 % in p_h) and above 0.6 of
//   Janssen with K = 0.5 (0.76 measured in the band 0.8-1.0 m, leaving 20 % for the
//   particle-scale scatter of one band of 16 rows).
// - Wall friction fully mobilised, as Janssen assumes: friction / (mu p_h) per band between
//   0.85 and Coulomb's bound 1 (measured 0.91-0.98).
// - Vertical equilibrium: the floor and the walls' friction carry the weight of the fill, a
//   conservation law. The kinetic energy left at 3.5 s is 1.9e-5 J: were it all in the
//   column's first elastic mode (period 2 H / c = 36 ms) the floor load would ring by at most
//   m omega v = 0.4 % of the weight; 1 % asserted.
TEST(SiloRestValidation, WallPressureAtRestAgainstJanssen) {
    const CaseRun run = run_case_file("cases/silo/silo_rest.toml", "silo_rest");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_LT(result_value(summary, "settle_time"), 3.5); // measured 2.032 s
    const SiloRest rest =
        read_silo_rest(run.out, frame_path(run.out, "silo_rest", 35), kSpacing, kParticleMass);
    ASSERT_EQ(rest.bands.size(), 4u);
    constexpr double kEquilibrium = 1e-2;
    EXPECT_NEAR(rest.carried_fraction, 1.0, kEquilibrium);
    constexpr double kLowestFraction = 0.6;
    constexpr double kMobilised = 0.85;
    expect_bands_against_janssen(rest, kLowestFraction, kMobilised);
}

} // namespace
} // namespace grainload::testing
