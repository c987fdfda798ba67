// A body whose drawn size the lattice rounds says so, in `grainload check` and in summary.json,
// end to end through the CLI on a free-flight scene (no interactions: the run costs nothing).

#include "support/case_runner.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <regex>
#include <string>

namespace grainload::testing {
namespace {

// A cylinder 40 mm across and 40 mm high filled at 3 mm: 13 cells high (39 mm), 14 across
// (42 mm) (tests/unit/sph/body_generator_test.cpp); a box of whole spacings beside it is filled
// as drawn and is not mentioned.
constexpr const char* kCase = R"(
[case]
name = "rounded"
dimension = 3
end_time = "2 ms"
output_interval = "1 ms"

[[material]]
name = "sand"
model = "linear_elastic"
density = "1600 kg/m^3"
youngs_modulus = "10 MPa"
poisson_ratio = 0.3

[sph]
interactions = false
time_step = "1 ms"

[[sph.body]]
name = "cylinder"
material = "sand"
spacing = "3 mm"

[sph.body.shape]
type = "cylinder"
base = "0 0 0 mm"
axis = "0 0 1"
radius = "20 mm"
height = "40 mm"

[[sph.body]]
name = "block"
material = "sand"
spacing = "3 mm"

[sph.body.shape]
type = "box"
min = "100 0 0 mm"
max = "112 12 12 mm"
)";

/// The figure `name` of a summary.json text as written: value, reference and relative error.
std::smatch figure(const std::string& summary, const std::string& name) {
    const std::regex pattern("\"" + name +
                             "\": \\{\"value\": ([-+0-9.eE]+), \"unit\": \"m\", \"reference\": "
                             "([-+0-9.eE]+)[^}]*\"relative_error\": ([-+0-9.eE]+)");
    std::smatch match;
    EXPECT_TRUE(std::regex_search(summary, match, pattern)) << name << " in " << summary;
    return match;
}

// `check` prints the drawn and filled sizes of the rounded body, per axis, and leaves the block
// alone; the run's summary.json carries each as a figure (the filled size) beside its
// reference (the drawn size) and their relative error: 39 against 40 mm, 2.5 %.
TEST(LatticeRounding, ABodyTheLatticeRoundsSaysSoInCheckAndSummary) {
    const std::string folder = test_folder("lattice_rounding");
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    std::ofstream(folder + "/rounded.toml") << kCase;
    const CliResult check = run_cli("check '" + folder + "/rounded.toml'", folder + "/check.log");
    ASSERT_EQ(check.exit_code, 0) << check.output;
    EXPECT_NE(check.output.find("body \"cylinder\" is filled by the 3 mm lattice to another size "
                                "than drawn: x 40 mm drawn, 42 mm filled (14 cells); y 40 mm "
                                "drawn, 42 mm filled (14 cells); z 40 mm drawn, 39 mm filled "
                                "(13 cells)"),
              std::string::npos)
        << check.output;
    EXPECT_EQ(check.output.find("body \"block\" is filled"), std::string::npos) << check.output;

    const CliResult run = run_cli("run '" + folder + "/rounded.toml' --out '" + folder + "/out'",
                                  folder + "/run.log");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const std::string summary = read_file(folder + "/out/summary.json");
    const auto z = figure(summary, "body_cylinder_size_z");
    ASSERT_EQ(z.size(), 4u);
    EXPECT_NEAR(std::stod(z[1]), 0.039, 1e-12);
    EXPECT_NEAR(std::stod(z[2]), 0.040, 1e-12);
    EXPECT_NEAR(std::stod(z[3]), 0.025, 1e-9);
    const auto x = figure(summary, "body_cylinder_size_x");
    ASSERT_EQ(x.size(), 4u);
    EXPECT_NEAR(std::stod(x[1]), 0.042, 1e-12);
    EXPECT_EQ(summary.find("body_block_size"), std::string::npos) << summary;
}

} // namespace
} // namespace grainload::testing
