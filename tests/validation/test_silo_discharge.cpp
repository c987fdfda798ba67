#include "support/case_runner.hpp"

#include <cmath>
#include <iostream>
#include <string>

namespace grainload::testing {
namespace {

// The slot silo's discharge at the case file's resolution (cases/silo/silo_discharge.toml,
// 12.5 mm; docs/validation/silo.md, "At 12.5 mm"): filled to 2 s, settled, the gate removed
// at 2.3 s, the outlet drawn 0.265 m wide for 0.2 m in effect (the contact reach 2h narrows
// each edge). About 4-10 min on 2 threads.
constexpr double kBulkDensity = 1500.0; // kg/m^3, the continuum's
constexpr double kGravity = 9.81;
constexpr double kSlotConstant = 1.03; // C' of Beverloo's slot law (Nedderman 1992)
constexpr double kOutlet = 0.2;        // m, in effect: 0.265 m drawn less 2 x 2h

// Reference: Beverloo's slot law per metre, W = C' rho_b sqrt(g) B^(3/2) with C' = 1.03 and
// k d = 0 (a continuum has no grain): 432.8 kg/m/s. grainload's steady rate stands above it by
// a documented gap: 497.4 kg/m/s (2026-12-02) and 504.4 kg/m/s (2026-12-05), a round-off
// ensemble of four 504.1 kg/m/s +- 0.22 %, i.e. 1.15-1.165 x Beverloo (inside C''s spread
// across materials, up to a factor of 2: Darias, Madrid & Pugnaloni 2017). Asserted: 1.10-1.22 x
// Beverloo, the documented ratio with 5 % on either side. The trade table at this spacing moves the
// rate by at most 1.1 % over stiffness 1-0.25 and CFL 0.3-0.6, well inside; an outlet as wide as
// drawn, its edges no longer narrowed by the contact reach, would flow (0.265 / 0.2)^(3/2) = 1.53
// times faster and leave it. Mass audit: scene + discharged = created, to the round-off of sums of
// at most 4000 equal particle masses (4000 eps).
TEST(SiloDischargeValidation, SteadyRateAgainstBeverloo) {
    const CaseRun run = run_case_file("cases/silo/silo_discharge.toml", "silo_discharge");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_LT(std::abs(result_value(summary, "mass_audit_error")), 4000 * 2.2e-16);
    const double rate = result_value(summary, "sink_below_steady_rate");
    const double beverloo =
        kSlotConstant * kBulkDensity * std::sqrt(kGravity) * std::pow(kOutlet, 1.5);
    std::cout << "steady rate " << rate << " kg/m/s, Beverloo " << beverloo << " kg/m/s, ratio "
              << rate / beverloo << '\n';
    EXPECT_GT(rate / beverloo, 1.10);
    EXPECT_LT(rate / beverloo, 1.22);
}

} // namespace
} // namespace grainload::testing
