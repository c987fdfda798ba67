#include "support/case_runner.hpp"
#include "support/coupling_figures.hpp"

#include <string>

namespace grainload::testing {
namespace {

// cases/sand_on_plate/sand_fill_plate_small.toml: a coupled tray filled by a source while a
// spilled row falls into a sink. Particles of 1600 kg/m^3 x (20 mm)^3.
constexpr const char* kCase = "cases/sand_on_plate/sand_fill_plate_small.toml";
constexpr double kParticleMass = 0.0128;          // kg
constexpr double kGravity = 9.81;                 // m/s^2
constexpr double kTrayMass = 2000 * 0.0128;       // the first layer and the four created
constexpr double kSpillMass = 20 * 0.0128;        // the row below the plate
constexpr double kAuditRoundOff = 2100 * 2.2e-16; // sums of about 2000 equal masses

// The source owes 102.4 kg/s over its 0.2 s, exactly 1600 particles, and every site is free
// when its row's turn comes (created at rest where the placed layer has its particles), so
// it creates them all. The spilled row falls 0.3 m in 0.25 s and leaves through the sink.
// Once settled (after 0.35 s), the plate's mean load over the windows (coupling.csv) and the
// side walls' vertical forces carry the tray's weight: momentum balance of a body at rest.
// Bound 0.2 %: the layer sloshes by ±0.2 % of its weight at rest (measured after 0.35 s), the
// mean over 0.25 s takes most of it out (measured 0.005 %).
TEST(CouplingFillSmall, ATrayFilledByASourceCarriesWhatTheSourceCreated) {
    const CaseRun run = run_case_file(kCase, "sand_fill_plate_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_NEAR(result_value(summary, "created_mass"), 1600 * kParticleMass, kAuditRoundOff);
    EXPECT_NEAR(result_value(summary, "sink_below_discharged_mass"), kSpillMass, kAuditRoundOff);
    EXPECT_LT(std::abs(result_value(summary, "mass_audit_error")), kAuditRoundOff);
    double time = 0.0;
    const double load = -mean_shell_load_z(run.out, 0.35, time);
    ASSERT_GT(time, 0.2);
    const double side_walls = walls_force_z(summary, {"x0", "x1", "y0", "y1"});
    const double weight = kTrayMass * kGravity;
    std::cout << "filled tray: mean plate load " << load << " N, side walls " << side_walls
              << " N, weight " << weight << " N\n";
    EXPECT_NEAR(load - side_walls, weight, 2e-3 * weight);
}

// Iterated windows run every pass from the window's start state: the particles created and
// removed at the window's end must be neither repeated nor lost across the passes. The
// books close to round-off and the particles in the scene are the initial ones plus the
// created minus the discharged, counted in particles (a pass that created twice would add
// a row).
TEST(CouplingFillSmall, IteratedWindowsCreateAndRemoveEachParticleOnce) {
    const CaseRun run =
        run_case_file(kCase, "sand_fill_plate_iterated",
                      "--set coupling.max_iterations=4 --set 'case.end_time=0.3 s'");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_LT(std::abs(result_value(summary, "mass_audit_error")), kAuditRoundOff);
    EXPECT_NEAR(result_value(summary, "created_mass"), 1600 * kParticleMass, kAuditRoundOff);
    EXPECT_NEAR(result_value(summary, "sink_below_discharged_mass"), kSpillMass, kAuditRoundOff);
    EXPECT_NEAR(result_value(summary, "scene_mass"), kTrayMass, kAuditRoundOff);
}

// A coupled run stopped at 0.1 s, while the source creates, and restarted ends at 0.2 s bit
// for bit where the uninterrupted run ends.
TEST(CouplingFillSmall, RestartDuringCreationReproducesTheCoupledRun) {
    const std::string base = test_folder("coupled_fill_restart");
    ASSERT_EQ(run_whole_and_split(kCase, base, "0.1 s", "0.2 s"), "");
    const std::string a = read_file(base + "_whole/summary.json");
    const std::string b = read_file(base + "_split/summary.json");
    for (const char* figure : {"created_mass", "kinetic_energy", "interface_force_z",
                               "centre_deflection", "discharged_mass"}) {
        EXPECT_EQ(result_value(a, figure), result_value(b, figure)) << figure;
    }
}

} // namespace
} // namespace grainload::testing
