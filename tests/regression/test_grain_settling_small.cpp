// DEM beads settling in a box, placed or rained in (spheres or clumps), run from the command
// line as a user runs it: at rest the walls carry their weight; what the source made is in the box;
// a run killed and restarted writes what the uninterrupted run writes.

#include "support/case_runner.hpp"
#include "support/gold_summary.hpp"
#include "support/interrupted_run.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace {

using namespace grainload::testing;

constexpr const char* kCase = "cases/grain_settling/grain_settling_small.toml";

// At rest the walls carry the grains' weight: static equilibrium, the reference the model
// states beside the figure. What still moves at 0.6 s (kinetic energy 2e-7 J against the
// fall's 0.14 J) changes the load by its momentum's rate: measured 3.7e-4 of the weight, bound
// 2e-3. The mean contact count of grains with each other, walls left out, lies below the
// isostatic 6 of frictionless spheres and near the 4 of very frictional ones (Silbert et al.
// 2002, Phys. Rev. E 65); the walls' neighbours lower it (measured 3.7): bound [3, 6].
TEST(GrainSettlingSmall, AtRestTheWallsCarryTheGrainsWeight) {
    const CaseRun run = run_case_file(kCase, "grain_settling_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    const FigureReference load = figure_reference(summary, "walls_load_along_gravity");
    EXPECT_LT(load.relative_error, 2e-3) << load.value << " N against " << load.reference;
    EXPECT_LT(result_value(summary, "kinetic_energy"), 1e-6);
    EXPECT_GT(result_value(summary, "coordination_number"), 3.0);
    EXPECT_LT(result_value(summary, "coordination_number"), 6.0);
    EXPECT_LT(result_value(summary, "deepest_overlap"), 0.01);
    expect_matches_gold(run.out, kCase);
}

// The same box filled with 100 clumps of any shape (an L of three touching spheres, its
// inertia from its tensor), placed turned at random: at rest the walls carry their weight, as
// for the beads (measured 1.0e-4 above it, kinetic energy 1.7e-10 J; bound 2e-3).
TEST(GrainSettlingSmall, ClumpsOfAnyShapeComeToRestOnTheWalls) {
    const CaseRun run =
        run_case_file(kCase, "grain_settling_l_clumps",
                      "--set 'dem.body[0].sphere_centres=[0, 0, 0, 2, 0, 0, 0, 2, 0]' --set "
                      "'dem.body[0].count=100' --threads 1");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_EQ(result_value(summary, "grains"), 100.0);
    const FigureReference load = figure_reference(summary, "walls_load_along_gravity");
    EXPECT_LT(load.relative_error, 2e-3) << load.value << " N against " << load.reference;
    EXPECT_LT(result_value(summary, "kinetic_energy"), 1e-6);
}

// SIGKILL at random moments after the first checkpoint and a restart: frames, wall_forces.csv,
// log and summary equal the uninterrupted run's (grains, their springs and the neighbour list
// restored bit for bit).
TEST(GrainSettlingSmall, KilledAndRestartedReproducesTheUninterruptedRun) {
    const std::vector<std::string> arguments = {
        "run",   source_path(kCase),           "--set",     "case.end_time=0.2 s",
        "--set", "case.output_interval=10 ms", "--threads", "1"};
    expect_restarts_reproduce_the_run(arguments, "grain_settling", 2);
}

constexpr const char* kRainCase = "cases/grain_rain/grain_rain_small.toml";

/// The rain case run with `options`: all 150 grains made and in the box, the mass audit
/// balanced to round-off, and near rest at 0.8 s the walls carry the grains' weight to 5e-3;
/// the figures as the case's gold file holds them where `gold`.
void expect_the_rain_fills_the_box(const std::string& name, const std::string& options, bool gold) {
    const CaseRun run = run_case_file(kRainCase, name, options);
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_EQ(result_value(summary, "source_feed_created"), 150.0);
    EXPECT_EQ(result_value(summary, "grains"), 150.0);
    EXPECT_LT(std::abs(result_value(summary, "mass_audit_error")), 1e-12);
    const FigureReference load = figure_reference(summary, "walls_load_along_gravity");
    EXPECT_LT(load.relative_error, 5e-3) << load.value << " N against " << load.reference;
    if (gold) {
        expect_matches_gold(run.out, kRainCase);
    }
}

// 150 beads rained in by a source: every one made and in the box, and near rest the walls
// carry their weight: measured 1.9e-3 above it (what still moves, kinetic energy 1.7e-4 J
// against the fall's 0.2 J), bound 5e-3.
TEST(GrainRainSmall, TheSourcesGrainsFillTheBoxAndTheWallsCarryThem) {
    expect_the_rain_fills_the_box("grain_rain_small", "", true);
}

// The same source raining clumps of two touching spheres, each turned at random: all made and
// in the box, and near rest the walls carry their weight: measured 3.7e-3 below it (the clumps
// still settle: kinetic energy 3.5e-7 J), bound 5e-3 as for the beads.
TEST(GrainRainSmall, ClumpsRainedFillTheBoxAndTheWallsCarryThem) {
    expect_the_rain_fills_the_box("grain_rain_clumps", "--set 'dem.body[0].spheres=2' --threads 1",
                                  false);
}

// SIGKILL at random moments while the beads rain in, and a restart: frames, wall_forces.csv,
// the log and summary equal the uninterrupted run's (the source's generator, its running sum
// and the grains it made travel in the checkpoint).
TEST(GrainRainSmall, KilledAndRestartedReproducesTheUninterruptedRun) {
    const std::vector<std::string> arguments = {
        "run",   source_path(kRainCase),       "--set",     "case.end_time=0.25 s",
        "--set", "case.output_interval=10 ms", "--threads", "1"};
    expect_restarts_reproduce_the_run(arguments, "grain_rain", 2);
}

} // namespace
