#include "support/case_runner.hpp"

#include <cmath>
#include <filesystem>
#include <string>

namespace grainload::testing {
namespace {

// The source of the CI silo (cases/silo/silo_rest_small.toml): 400 kg/(m s) from t = 0,
// particles of 1500 kg/m^3 x (25 mm)^2 = 0.9375 kg/m created at rest, row by row up a box as
// tall as the fill, so in the first 0.6 s (the lowest 17 rows) every site above the fill is
// free when its turn comes. docs/validation/silo.md.
constexpr double kRate = 400.0;                     // kg/(m s)
constexpr double kParticleMass = 0.9375;            // kg/m
constexpr double kInitialMass = 15 * kParticleMass; // the one-layer body on the floor

// Created mass: the source owes rate * t and creates whole particles, so what it created lies
// within one particle mass below rate * t. Audit: sums of at most 400 equal masses, round-off
// below 400 eps. Created energy: every particle enters at rest, so the books hold exactly 0.
TEST(SiloFillSmall, SourceCreatesItsRateAndTheBooksCloseOverIt) {
    const CaseRun run = run_case_file("cases/silo/silo_rest_small.toml", "silo_fill_small",
                                      "--set 'case.end_time=0.6 s'");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    const double created = result_value(summary, "created_mass");
    EXPECT_LE(created, kRate * 0.6 + 1e-9);
    EXPECT_GT(created, kRate * 0.6 - kParticleMass);
    EXPECT_DOUBLE_EQ(result_value(summary, "initial_mass"), kInitialMass);
    constexpr double kRoundOff = 400 * 2.2e-16;
    EXPECT_LT(std::abs(result_value(summary, "mass_audit_error")), kRoundOff);
    EXPECT_EQ(result_value(summary, "created_energy"), 0.0);
}

// A run stopped at 0.3 s while the source is creating and restarted from its checkpoint ends
// at 0.6 s bit for bit where the uninterrupted run ends: the checkpoint replays the created
// particles and holds what the source still owes and where its round-robin stands. The wall
// map's window (the whole run) spans the restart: its sums travel in the checkpoint.
TEST(SiloFillSmall, RestartDuringCreationReproducesTheUninterruptedRun) {
    const std::string base = test_folder("silo_fill_restart");
    ASSERT_EQ(run_whole_and_split("cases/silo/silo_rest_small.toml", base, "0.3 s", "0.6 s"), "");
    const std::string frame = "/frames/silo_rest_small_000006/sand.vtp";
    const std::string whole = read_file(base + "_whole" + frame);
    ASSERT_GT(whole.size(), 1000u);
    EXPECT_TRUE(whole == read_file(base + "_split" + frame)) << "the sand's frame at 0.6 s";
    for (const char* map : {"/wall_maps/right_window.csv", "/wall_maps/right_000006.csv"}) {
        const std::string uninterrupted = read_file(base + "_whole" + map);
        ASSERT_GT(uninterrupted.size(), 100u) << map;
        EXPECT_TRUE(uninterrupted == read_file(base + "_split" + map)) << map;
    }
    const std::string a = read_file(base + "_whole/summary.json");
    const std::string b = read_file(base + "_split/summary.json");
    for (const char* figure : {"created_mass", "created_energy", "kinetic_energy", "gravity_work",
                               "energy_balance_error", "wall_left0_force_x"}) {
        EXPECT_EQ(result_value(a, figure), result_value(b, figure)) << figure;
    }
}

} // namespace
} // namespace grainload::testing
