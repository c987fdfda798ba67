// Coupled runs killed with SIGKILL at random moments and restarted from the checkpoint each
// left: every file the run writes (frames, wall_forces.csv, discharge.csv, coupling.csv,
// fem_convergence.csv, the log's events, summary.json) must equal the uninterrupted run's, and
// the killed run's tables must end in whole lines. The streamed tables are the wall-load
// history engineers size walls from: a restart once rewrote wall_forces.csv from the restart
// point, losing everything before it.

#include "support/cli_runner.hpp"
#include "support/interrupted_run.hpp"

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace {

using namespace grainload::testing;

// Three kills each: a kill lands at a uniformly drawn moment of the run, so three of them
// cover stepping, frame writing and checkpoint replacement in most runs of the suite, while
// keeping the test to about a minute on two cores.
constexpr int kKills = 3;

// A silo wall coupled as a static elastic shell (the Janssen verification case), to 0.3 s with a
// frame every 20 ms: the sand falls onto the floor and slides down the shell, which is solved
// every window (fem_convergence.csv, coupling.csv).
TEST(InterruptedCoupledRun, SiloWithAnElasticShellReproducesTheUninterruptedRun) {
    const std::vector<std::string> arguments = {
        "run",       source_path("cases/silo_janssen/silo_janssen_small.toml"),
        "--set",     "case.end_time=0.3 s",
        "--set",     "case.output_interval=20 ms",
        "--threads", "1"};
    expect_restarts_reproduce_the_run(arguments, "silo_janssen", kKills);
}

// The wagon slice, from the fill through the door's swing (1.5-2.0 s) to 1.7 s, a frame every
// 0.1 s: sources, sinks (discharge.csv), a rigid moving door and the rigid coupled body.
TEST(InterruptedCoupledRun, WagonSliceThroughItsDoorOpeningReproducesTheUninterruptedRun) {
    const std::vector<std::string> arguments = {
        "run",       source_path("cases/hopper_wagon/hopper_wagon_small.toml"),
        "--set",     "case.end_time=1.7 s",
        "--threads", "1"};
    expect_restarts_reproduce_the_run(arguments, "wagon_slice", kKills);
}

} // namespace
