#include "support/case_runner.hpp"
#include "support/csv_rows.hpp"
#include "support/gold_summary.hpp"
#include "support/silo_rest.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vtkPoints.h>

namespace grainload::testing {
namespace {

// The CI slot silo at rest (cases/silo/silo_rest_small.toml, docs/validation/silo.md): filled
// by its source to 1.7 s, settled, read at 3 s.
constexpr double kSpacing = 0.025;       // m
constexpr double kParticleMass = 0.9375; // kg/m
constexpr double kBand = SiloRestCase::band;

// - Vertical equilibrium at rest: the floor and the walls' friction carry the weight of what
//   is in the silo (kinetic energy 1e-13 J at 3 s): to 0.1 % (measured 1e-5; the contact
//   dashpot and the last ringing are below that).
// - Wall friction fully mobilised, as Janssen assumes: friction / (mu p_h) per band between
//   0.85 and 1 (Coulomb's bound; measured 0.92-0.97 in the bands clear of floor and surface).
// - p_h per band against Janssen with K = 1 - sin(phi) (0.5) and EN 1991-4's 1.1 (1 - sin
//   phi) (0.55): at 25 mm (15 particles across) the run's p_h is 0.74-0.89 of the bracket's
//   mean in the bands 0.2-1.0 m, because the continuum's own K, p_h / p_v, is 0.27-0.31, below
//   the bracket (docs/validation/silo.md). Asserted: p_h below Janssen with K = 0.55 (the
//   design bound stays conservative) and above 0.6 of Janssen with K = 0.5 (0.74 measured,
//   leaving 20 % for the particle-scale scatter of one band of 8 rows).
TEST(SiloRestSmall, WallPressureAtRestAgainstJanssen) {
    const CaseRun run = run_case_file("cases/silo/silo_rest_small.toml", "silo_rest_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_LT(result_value(summary, "settle_time"), 3.0);
    const SiloRest rest = read_silo_rest(run.out, frame_path(run.out, "silo_rest_small", 30),
                                         kSpacing, kParticleMass);
    ASSERT_EQ(rest.bands.size(), 4u);
    constexpr double kEquilibrium = 1e-3;
    EXPECT_NEAR(rest.carried_fraction, 1.0, kEquilibrium);
    constexpr double kLowestFraction = 0.6;
    constexpr double kMobilised = 0.85;
    expect_bands_against_janssen(rest, kLowestFraction, kMobilised);
    const auto& forces = rest.forces;

    // The right wall's map ([[sph.wall_map]] "right": 0.2 m bins, the mean over 2.9-3 s).
    // Its cells summed are the wall's force of wall_forces.csv at 3 s (the same particle forces,
    // binned and time-averaged, of a sand at rest: 0.5 %). Bin by bin it mirrors the left
    // wall's bands, which are separate walls: the fill is symmetric about the slot's middle,
    // so p_h agrees to the particle-scale scatter of a band of 8 rows (measured 1-4 % in the
    // bands 0.2-1.2 m; 10 % asserted).
    const auto cells = numeric_csv_rows(run.out + "/wall_maps/right_000030.csv");
    ASSERT_EQ(cells.size(), 8u);
    double normal = 0.0;
    double friction = 0.0;
    for (const auto& cell : cells) {
        normal += cell[4] * kBand;
        friction += cell[5] * kBand;
    }
    EXPECT_NEAR(normal, forces.at("right").first, 5e-3 * forces.at("right").first);
    EXPECT_NEAR(friction, forces.at("right").second, 5e-3 * std::abs(forces.at("right").second));
    for (int band = 1; band <= 5; ++band) {
        const double left = -forces.at("left" + std::to_string(band)).first / kBand;
        EXPECT_NEAR(cells[static_cast<std::size_t>(band)][4], left, 0.1 * left) << "band " << band;
    }
    expect_matches_gold(run.out, "cases/silo/silo_rest_small.toml");
}

} // namespace
} // namespace grainload::testing
