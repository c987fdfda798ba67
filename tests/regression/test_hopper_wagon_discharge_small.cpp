#include "support/case_runner.hpp"
#include "support/csv_rows.hpp"
#include "support/frame_reader.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

namespace grainload::testing {
namespace {

// cases/hopper_wagon/hopper_wagon_small.toml: a 1 m slice of the quarter wagon (between
// frictionless rigid planes at x = 1.5 and 2.5 m, the centre line a symmetry plane), filled
// to 0.5 s, settled, its door swung open from 1.5 s to 2.0 s; docs/validation/hopper_wagon.md.
constexpr double kGravity = 9.81;
constexpr double kDoorOpens = 1.5; // s
constexpr double kRestTime = 1.4;  // s: the last frame before the door moves

// One run, four checks: the mass audit, the load's weight carried by the walls before the
// door opens, nothing out before the door moves and the load running out after, and the
// symmetry plane never crossed.
TEST(HopperWagonDischargeSmall, HoldsItsWeightThenRunsOutThroughTheDoor) {
    const CaseRun run =
        run_case_copy("cases/hopper_wagon", {"hopper_wagon_small.toml", "hopper_wagon.geo"},
                      "hopper_wagon_discharge_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string& out = run.out;
    const std::string summary = read_file(out + "/summary.json");
    const double load =
        result_value(summary, "initial_mass") + result_value(summary, "created_mass");

    // Mass audit: scene + discharged = created, to the round-off of sums of ~600 masses.
    EXPECT_LT(std::abs(result_value(summary, "mass_audit_error")), 1e-13);

    // At rest before the door opens, the body (coupled shell, rigid here), the door and the
    // slice's planes carry the load's weight: a symmetry plane's images push on the load only
    // along its normal (the images' total force is its own mirror image negated, so its x and
    // z parts vanish). 0.2 %: what the load's remaining motion (0.9 s after the fill) leaves
    // in the frame's one-step forces; measured 0.015 % at 1.4 s, 0.02 % from 1.1 to 1.5 s.
    const double carried = walls_load_z(out, kRestTime);
    std::printf("load %.1f kg, weight %.1f N, carried by the walls at %.1f s: %.1f N\n", load,
                load * kGravity, kRestTime, carried);
    EXPECT_NEAR(carried, load * kGravity, 2e-3 * load * kGravity);

    // The door opening: nothing leaves while it is shut, and once it swings open the load runs
    // out: more than half of it by the end, 1.1 s after the door started to move (measured
    // 0.66; a door that opened but held the load back, as the stand-off of the contact
    // potential did with the door drawn at its own 700 mm, let out a few per cent).
    double before = 0.0;
    double after = 0.0;
    for (const auto& [time, mass] : discharge_rows(out)) {
        (time <= kDoorOpens ? before : after) = mass;
    }
    std::printf("discharged %.1f kg by %.1f s, %.1f kg (%.2f of the load) at the end\n", before,
                kDoorOpens, after, after / load);
    EXPECT_EQ(before, 0.0);
    EXPECT_GT(after, 0.5 * load);

    // The symmetry plane y = 0 is never crossed: every particle of every frame has y >= 0.
    EXPECT_EQ(count_frame_points(out, "load", [](const double* p) { return p[1] < 0.0; }), 0);
}

} // namespace
} // namespace grainload::testing
