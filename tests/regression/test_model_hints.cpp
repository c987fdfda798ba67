// What a run says it modelled and what it could have left out, end to end
// on the small 3D column collapse of the thesis sand (generalized cap, X0 = 0).

#include "support/case_runner.hpp"

#include <gtest/gtest.h>
#include <string>

namespace {

using namespace grainload::testing;

constexpr const char* kCase = "cases/column_collapse/column_collapse_small.toml";
constexpr const char* kShort = "--threads 2 --set 'case.end_time=0.05 s'";

// With X0 = 0 the cap starts at the origin of the I1 axis (MAT_025 semantics), so every
// particle that carries any compressive mean stress compacts on it: the hint must say the cap
// is needed, with a share above zero.
TEST(ModelHints, ACapAtTheOriginIsReachedAndSaysSo) {
    const CaseRun run = run_case_file(kCase, "hints_cap_reached", kShort);
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_NE(summary.find(") compacted on the cap: the cap is needed"), std::string::npos)
        << summary;
    EXPECT_NE(run.cli.output.find("hint: material 'sand' (generalized_cap): "), std::string::npos);
    // What was modelled: the scene's own choices, listed by name.
    EXPECT_NE(summary.find("\"material sand\": \"generalized_cap\""), std::string::npos);
    EXPECT_NE(summary.find("\"wall container\": \"rigid\""), std::string::npos);
    EXPECT_NE(summary.find("\"dimension\": \"3D\""), std::string::npos);
}

// The same column with the cap's initial intercept at 10 MPa: the column's largest stress is of
// order rho g H = 2099 * 9.81 * 0.19 m = 3.9 kPa (a few times that in the collapse's
// transients), four orders of magnitude below the cap, so no particle can compact on it and the
// hint must offer Drucker-Prager.
TEST(ModelHints, ACapFarAboveTheStressesIsNeverReachedAndSaysSo) {
    const CaseRun run =
        run_case_file(kCase, "hints_cap_unreached",
                      std::string(kShort) + " --set 'material[0].generalized_cap.cap_X0=10 MPa'");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_NE(summary.find("none of its 325 particles compacted on the cap; a drucker_prager "
                           "material"),
              std::string::npos)
        << summary;
}

} // namespace
