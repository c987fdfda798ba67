#include "support/case_runner.hpp"
#include "support/frame_reader.hpp"
#include "support/silo_janssen.hpp"

#include <cmath>
#include <iostream>
#include <string>

namespace grainload::testing {
namespace {

// The slot silo at rest at the case file's resolution (cases/silo/silo_rest.toml, 12.5 mm, 35
// particles across; docs/validation/silo.md, "Full version"): filled by its source to 2 s,
// settled, read at 3.5 s. About 5 min on 2 threads.
constexpr double kGravity = 9.81;
constexpr double kMu = 0.4;                // wall friction of the case
constexpr double kSinPhi = 0.5;            // phi = 30 deg
constexpr double kSpacing = 0.0125;        // m
constexpr double kParticleMass = 0.234375; // kg/m: 1500 kg/m^3 x (12.5 mm)^2
constexpr double kBand = 0.2;              // m, the left wall's bands left0 .. left5

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
    const auto sand = read_named_block(run.out + "/frames/silo_rest_000035.vtm", "sand");
    ASSERT_TRUE(sand);
    const SlotFill fill = measure_slot_fill(sand, kSpacing, kParticleMass, kGravity);
    const auto forces = final_wall_forces(run.out);
    double carried = -forces.at("floor").second - forces.at("right").second;
    for (const auto& [wall, force] : forces) {
        carried -= wall.rfind("left", 0) == 0 ? force.second : 0.0;
    }
    constexpr double kEquilibrium = 1e-2;
    EXPECT_NEAR(carried / (fill.mass * kGravity), 1.0, kEquilibrium);
    constexpr double kLowestFraction = 0.6;
    constexpr double kMobilised = 0.85;
    for (int band = 1; band <= 4; ++band) {
        const auto [fx, fy] = forces.at("left" + std::to_string(band));
        const double p_h = -fx / kBand;
        const double a = fill.surface - kBand * (band + 1);
        const double b = fill.surface - kBand * band;
        const double low = janssen_band(fill, 1.0 - kSinPhi, kMu, a, b);
        const double high = janssen_band(fill, 1.1 * (1.0 - kSinPhi), kMu, a, b);
        const double mobilised = -fy / (kMu * p_h * kBand);
        std::cout << "band " << band << ": p_h " << p_h << " Pa, Janssen K=0.5 " << low
                  << " Pa, K=0.55 " << high << " Pa, friction/(mu p_h) " << mobilised << '\n';
        EXPECT_LT(p_h, high) << "band " << band;
        EXPECT_GT(p_h, kLowestFraction * low) << "band " << band;
        EXPECT_GT(mobilised, kMobilised) << "band " << band;
        EXPECT_LE(mobilised, 1.0 + 1e-9) << "band " << band;
    }
}

} // namespace
} // namespace grainload::testing
