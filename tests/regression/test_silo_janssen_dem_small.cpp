// The circular silo in DEM, run from the command line: grains rained into a cylinder of mesh
// bands, settled, then the floor sinks half a millimetre. The floor and the bands carry the
// weight; each band's friction stays within Coulomb's bound of its normal load; the bands below
// the surface carry Janssen's (1895) profile; the wall map bins the same contacts by height and
// angle. Killed and restarted while the floor moves, the run writes what the uninterrupted run
// writes, the wall map's files included.

#include "support/case_runner.hpp"
#include "support/csv_rows.hpp"
#include "support/frame_reader.hpp"
#include "support/gold_summary.hpp"
#include "support/interrupted_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <numbers>
#include <vtkDataArray.h>
#include <vtkPointData.h>

namespace {

using namespace grainload::testing;

constexpr const char* kCase = "cases/silo_janssen/silo_janssen_dem_small.toml";
constexpr double kGravity = 9.81;
constexpr double kMuWall = 0.4;     // the case's wall friction
constexpr double kRadius = 0.075;   // the cylinder's (cylinder_band.stl at scale 0.5)
constexpr double kBand = 0.05;      // the bands' height
constexpr double kDensity = 2650.0; // the grains' material

/// The volume of a sphere (centre height z, radius r) between the planes z = low and z = high.
double slab_volume(double z, double r, double low, double high) {
    const double a = std::clamp(low - z, -r, r);
    const double b = std::clamp(high - z, -r, r);
    return std::numbers::pi * ((r * r * b - b * b * b / 3.0) - (r * r * a - a * a * a / 3.0));
}

/// The fill's bulk density: the grains' volume between 2 and 8 largest radii above the floor
/// (below the heap, above the floor's layering) over the slab's volume, times their density.
double bulk_density(const std::string& vtm) {
    const auto grains = read_particle_block(vtm, 0);
    const auto radius = grains->GetPointData()->GetArray("radius");
    double largest = 0.0;
    for (vtkIdType i = 0; i < grains->GetNumberOfPoints(); ++i) {
        largest = std::max(largest, radius->GetTuple1(i));
    }
    const double low = 2.0 * largest;
    const double high = 8.0 * largest;
    double volume = 0.0;
    for (vtkIdType i = 0; i < grains->GetNumberOfPoints(); ++i) {
        volume += slab_volume(grains->GetPoint(i)[2], radius->GetTuple1(i), low, high);
    }
    return kDensity * volume / (std::numbers::pi * kRadius * kRadius * (high - low));
}

/// Janssen's vertical stress at depth s: p_v = rho g D / (4 lambda) (1 - exp(-4 lambda s / D)),
/// lambda = mu K; a band from depth s_a to s_b carries what the slice's weight does not pass
/// down: rho g A (s_b - s_a) - A (p_v(s_b) - p_v(s_a)).
double janssen_band(double s_a, double s_b, double rho, double lambda) {
    const double d = 2.0 * kRadius;
    const double area = std::numbers::pi * kRadius * kRadius;
    const auto p_v = [&](double s) {
        return rho * kGravity * d / (4.0 * lambda) * (1.0 - std::exp(-4.0 * lambda * s / d));
    };
    return rho * kGravity * area * (s_b - s_a) - area * (p_v(s_b) - p_v(s_a));
}

/// The lambda = mu K whose wall share 1 - (1 - exp(-x)) / x (x = 4 lambda H / D) is `share`.
double fitted_lambda(double share, double height) {
    double low = 1e-6;
    double high = 10.0;
    for (int i = 0; i < 200; ++i) {
        const double lambda = 0.5 * (low + high);
        const double x = 4.0 * lambda * height / (2.0 * kRadius);
        (1.0 - (1.0 - std::exp(-x)) / x < share ? low : high) = lambda;
    }
    return 0.5 * (low + high);
}

// The wall map bins the contacts the bands sum, each where it acts: per row of the map (a
// band's height) its cells' mean pressure times their area is the band's normal force, and the
// map's resultants are the bands' normal force and friction. The map holds the mean over the
// last 0.1 s and the bands their loads at its end; at rest they differ by what still moves:
// measured 0.25 % at most a loaded row, 7e-5 and 5e-4 the resultants. Bounds: a row 1 % of its
// band or 1e-3 of the wall's normal force (the top rows hold a few contacts, 0.01 N), the
// resultants 5e-3.
constexpr double kRowTolerance = 0.01;
constexpr double kRowFloor = 1e-3;
constexpr double kResultantTolerance = 5e-3;

void expect_the_map_bins_the_bands(const std::string& out, const std::string& summary) {
    const auto rows = numeric_csv_rows(out + "/wall_maps/wall_window.csv");
    ASSERT_EQ(rows.size(), 60u);
    const double cell = kRadius * (2.0 * std::numbers::pi / 12.0) * kBand;
    std::vector<double> bands;
    double normal = 0.0;
    double friction = 0.0;
    for (int b = 0; b < 5; ++b) {
        const std::string band = "wall_band" + std::to_string(b);
        bands.push_back(result_value(summary, band + "_normal_force"));
        normal += bands.back();
        friction -= result_value(summary, band + "_force_z");
    }
    for (int b = 0; b < 5; ++b) {
        double row = 0.0;
        for (int sector = 0; sector < 12; ++sector) {
            const auto& values = rows[static_cast<std::size_t>(12 * b + sector)];
            EXPECT_NEAR(values[2], kBand * (b + 0.5), 1e-12); // the row's height
            row += values[4] * cell;                          // mean pressure x area
        }
        const double band = bands[static_cast<std::size_t>(b)];
        std::printf("row %d: %.4f N against the band's %.4f N\n", b, row, band);
        EXPECT_NEAR(row, band, std::max(kRowTolerance * band, kRowFloor * normal)) << "row " << b;
    }
    const double map_normal = result_value(summary, "wall_map_wall_normal_force");
    const double map_friction = -result_value(summary, "wall_map_wall_shear_axial_force");
    std::printf("map: normal %.4f N, friction %.4f N; bands %.4f N, %.4f N\n", map_normal,
                map_friction, normal, friction);
    EXPECT_NEAR(map_normal, normal, kResultantTolerance * normal);
    EXPECT_NEAR(map_friction, friction, kResultantTolerance * friction);
}

// Static equilibrium: the floor and the five bands carry the grains' weight (measured 2.2e-5;
// what moves at 1.3 s changes the load by its momentum's rate; bound 1e-3). Coulomb: a band's
// vertical load is the sum of its contacts' friction, each at most mu_w times its normal force,
// so it is at most mu_w times the band's normal force (bound exact, 1e-12 of it for the sums).
// Janssen: the settled floor mobilises the wall's friction (before it sinks the wall carries
// 0.4 % of the weight: the pouring's rebound, docs/validation/silo.md); with the one parameter
// lambda = mu K that gives the wall's share, the two bands below the surface carry Janssen's
// loads within 15 % (measured 2.9 % and 11 %): a band holds about 140 wall contacts of
// 11.5 grains across, whose chains scatter a band's load by about 1/sqrt(140) = 8.5 %.
TEST(SiloJanssenDemSmall, TheSettledFloorLeavesTheWallJanssensProfile) {
    const CaseRun run = run_case_file(kCase, "silo_janssen_dem_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_EQ(result_value(summary, "grains"), 1300.0);
    const double weight = result_value(summary, "scene_mass") * kGravity;
    double walls = 0.0;
    std::vector<double> loads;
    for (int b = 0; b < 5; ++b) {
        const std::string band = "wall_band" + std::to_string(b);
        loads.push_back(-result_value(summary, band + "_force_z"));
        const double normal = result_value(summary, band + "_normal_force");
        EXPECT_LE(loads.back(), kMuWall * normal * (1.0 + 1e-12)) << band;
        walls += loads.back();
    }
    const double floor = -result_value(summary, "wall_floor_force_z");
    EXPECT_NEAR(floor + walls, weight, 1e-3 * weight);
    expect_the_map_bins_the_bands(run.out, summary);
    const double rho = bulk_density(frame_path(run.out, "silo_janssen_dem_small", 26));
    const double height = weight / (rho * kGravity * std::numbers::pi * kRadius * kRadius);
    const double lambda = fitted_lambda(walls / weight, height);
    for (int b = 0; b < 2; ++b) {
        const double s_a = height - kBand * (b + 1);
        const double expected = janssen_band(s_a, s_a + kBand, rho, lambda);
        std::printf("band %d: %.4f N, Janssen %.4f N (rho_b %.1f kg/m^3, H %.4f m, mu K %.4f)\n", b,
                    loads[static_cast<std::size_t>(b)], expected, rho, height, lambda);
        EXPECT_NEAR(loads[static_cast<std::size_t>(b)], expected, 0.15 * expected);
    }
    expect_matches_gold(run.out, kCase);
}

// SIGKILL at random moments while grains land on a floor that sinks from 0.1 s to 0.3 s, and a
// restart: the floor's place and velocity follow from the time, so every output equals the
// uninterrupted run's.
TEST(SiloJanssenDemSmall, KilledAndRestartedWhileTheFloorMovesReproducesTheRun) {
    const std::vector<std::string> arguments = {
        "run",   source_path(kCase),           "--set",     "case.end_time=0.3 s",
        "--set", "case.output_interval=10 ms", "--set",     "dem.wall[0].move_start=0.1 s",
        "--set", "dem.wall[0].move_end=0.3 s", "--threads", "1"};
    expect_restarts_reproduce_the_run(arguments, "silo_janssen_dem", 2);
}

} // namespace
