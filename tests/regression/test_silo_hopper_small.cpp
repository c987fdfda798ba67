#include "support/case_runner.hpp"
#include "support/csv_rows.hpp"
#include "support/frame_reader.hpp"
#include "support/gold_summary.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

namespace grainload::testing {
namespace {

// cases/silo_hopper/silo_hopper_small.toml: the quarter of a circular silo (radius 0.2 m, a
// 0.4 m slice of its cylinder) with a 30 deg conical hopper, rigid walls where the steel shell
// is built; a placed cone of sand on a gate under the outlet, the cylinder filled by a source
// to 1.2 s, the gate removed as the discharge phase begins (the settle phase ends when the watch
// fires: the case's [[phase]] table); docs/validation/silo_hopper.md.
constexpr double kGravity = 9.81;
constexpr double kRestTime = 1.3; // s: the last frame before the gate leaves
constexpr double kWallFriction = 0.4;

// One run, five checks: the mass audit, the weight carried at rest, the wall friction within
// Coulomb's bound, nothing out before the gate goes and the sand running out after, and the
// symmetry planes never crossed.
TEST(SiloHopperSmall, HoldsItsWeightThenDischargesThroughTheOutlet) {
    const CaseRun run = run_case_copy(
        "cases/silo_hopper", {"silo_hopper_small.toml", "silo_hopper.geo"}, "silo_hopper_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string& out = run.out;
    const std::string summary = read_file(out + "/summary.json");
    const double sand =
        result_value(summary, "initial_mass") + result_value(summary, "created_mass");

    // Mass audit: scene + discharged = created, to the round-off of sums of ~900 masses.
    EXPECT_LT(std::abs(result_value(summary, "mass_audit_error")), 1e-13);

    // At rest, the gate, the hopper and the cylinder carry the sand's weight: the symmetry
    // planes' images push only along their normals (x and y). 1 %: the frame's forces are one
    // step's, 0.1 s after the source stopped, while the fill's last motion dies out (measured
    // +0.2 % at 1.3 s; -0.6 % at 1.2 s, when the last rows had just been created).
    const double carried = walls_load_z(out, kRestTime);
    std::printf("sand %.3f kg, weight %.2f N, carried at %.1f s: %.2f N\n", sand, sand * kGravity,
                kRestTime, carried);
    EXPECT_NEAR(carried, sand * kGravity, 1e-2 * sand * kGravity);

    // Janssen's wall friction, mobilised by the filling: on the cylinder the friction traction
    // (axial resultant of the unrolled map at rest, 1.2-1.3 s) stays within Coulomb's mu times
    // the normal force (each wall particle's friction is capped at mu times its normal contact
    // force; 1 % for the dashpot's share of the normal force, which the map counts), and the
    // rows created above slid the sand down the wall by enough to mobilise more than half of it
    // (measured 0.87 mu).
    const double normal = result_value(summary, "wall_map_rest_normal_force");
    const double shear = -result_value(summary, "wall_map_rest_shear_axial_force");
    std::printf("cylinder at rest: normal %.2f N, friction %.2f N (%.3f of mu N)\n", normal, shear,
                shear / (kWallFriction * normal));
    EXPECT_GT(shear, 0.5 * kWallFriction * normal);
    EXPECT_LT(shear, 1.01 * kWallFriction * normal);

    // The outlet: nothing leaves while the gate holds, and once it goes the sand runs out at a
    // rate that stays up (the steady rate over the run's linear part is more than half the mean
    // rate from the opening to the end: a jammed or choking outlet would fall far below it).
    const double opened = result_value(summary, "settle_time");
    double before = 0.0;
    double after = 0.0;
    for (const auto& [time, mass] : discharge_rows(out)) {
        (time <= opened ? before : after) = mass;
    }
    const double steady = result_value(summary, "sink_below_steady_rate");
    std::printf("gate removed at %.3f s; discharged %.3f kg, steady rate %.3f kg/s\n", opened,
                after, steady);
    EXPECT_EQ(before, 0.0);
    EXPECT_GT(after, 0.0);
    EXPECT_GT(steady, 0.5 * after / (2.6 - opened));

    // The symmetry planes x = 0 and y = 0 are never crossed.
    EXPECT_EQ(
        count_frame_points(out, "sand", [](const double* p) { return p[0] < 0.0 || p[1] < 0.0; }),
        0);
    expect_matches_gold(out, "cases/silo_hopper/silo_hopper_small.toml");
}

} // namespace
} // namespace grainload::testing
