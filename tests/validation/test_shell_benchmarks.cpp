#include "support/case_runner.hpp"

#include <cmath>
#include <iostream>
#include <string>

namespace grainload::testing {
namespace {

// The shell benchmarks of cases/shell_benchmarks/ at the finest meshes of
// docs/validation/shell_benchmarks.md, run through the CLI with the meshes refined by --set:
// each case's monitor writes its displacement beside the published value (MacNeal & Harder
// 1985) into summary.json. The test computes the error itself from the value and the
// published reference. A few seconds each.

/// Runs `case_file` with `options` and returns its monitor `name`: value and reference.
FigureReference run_benchmark(const std::string& case_file, const std::string& folder,
                              const std::string& options, const std::string& name) {
    const CaseRun run = run_case_file(case_file, folder, options);
    EXPECT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const FigureReference figure = figure_reference(read_file(run.out + "/summary.json"), name);
    std::cout << folder << ": " << figure.value << " m against " << figure.reference << " m ("
              << 100.0 * (figure.value / figure.reference - 1.0) << " %)\n";
    return figure;
}

// Scordelis-Lo roof, quarter model, 128 x 128 MITC4 elements (98 816 DOF): the free edge's
// mid-span deflection against the published 0.3024 m. The page measures -0.19 % (CalculiX S4
// -0.22 % on the same mesh), converging from -0.55 % and -0.32 % at 32 and 64, so its limit
// lies within about 0.1 % of the published value. Tolerance 0.5 %: the documented error with
// room for the last digit of the published value, and tight enough that a locking or
// over-soft element shows (the 16 x 16 mesh is -1.07 % off).
TEST(ShellBenchmarksValidation, ScordelisLoRoofAt128x128) {
    const FigureReference roof = run_benchmark(
        "cases/shell_benchmarks/scordelis_lo.toml", "scordelis_lo_128",
        "--set 'fem.shell[0].elements_around=128' --set 'fem.shell[0].elements_along=128'",
        "free edge mid-span deflection");
    EXPECT_NEAR(roof.reference, 0.3024, 1e-12); // the published value, as the case file cites it
    EXPECT_NEAR(roof.value, 0.3024, 0.005 * 0.3024);
}

// Pinched hemisphere with an 18 deg hole, quarter model, 64 x 64 elements (24 959 DOF): the
// radial displacement under the load against the published 0.094 m. The page measures
// -0.53 % (-0.95 % at 16 x 16). Tolerance 1 %: the published value has two digits (0.094 is
// +-0.53 % by its rounding alone), and the documented error lies within that rounding.
TEST(ShellBenchmarksValidation, PinchedHemisphereAt64x64) {
    const FigureReference hemisphere = run_benchmark(
        "cases/shell_benchmarks/pinched_hemisphere.toml", "pinched_hemisphere_64",
        "--set 'fem.shell[0].elements_polar=64' --set 'fem.shell[0].elements_around=64'",
        "radial displacement under the load");
    EXPECT_NEAR(hemisphere.reference, 0.094, 1e-12);
    EXPECT_NEAR(hemisphere.value, 0.094, 0.01 * 0.094);
}

} // namespace
} // namespace grainload::testing
