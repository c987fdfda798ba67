// The 2D column collapse with the mu(I) material (cases/column_collapse_2d/
// column_collapse_2d_mu_i_small.toml), run through the CLI as a user runs it.
//
// 1. With mu_2 = mu_s the law has no rate effect, so the SPH run must be the Drucker-Prager run
//    of the same cone (the case's [material.drucker_prager] table, switched with --set) to the
//    bit: the step's length reaches the material, and the mu(I) path through the stress update
//    changes nothing at rest.
// 2. With the case's law the run must differ from it (the rate is read), and keep its energy
//    books as the Drucker-Prager collapse does (potential energy lost = kinetic + internal +
//    contact energy, to 1 %: leapfrog's O(dt^2) error, measured 0.09 % for Drucker-Prager), and
//    come to rest (kinetic energy below 1e-4 of its peak, the heap figures' rest criterion).

#include "support/case_runner.hpp"
#include "support/frame_reader.hpp"
#include "support/gold_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <string>
#include <vector>
#include <vtkDataArray.h>
#include <vtkPointData.h>

namespace {

using namespace grainload::testing;

constexpr const char* kCase = "cases/column_collapse_2d/column_collapse_2d_mu_i_small.toml";
constexpr const char* kShort = " --set 'case.end_time=0.3 s'";

/// Positions of the column's particles in the run's frame `frame`.
std::vector<double> positions(const std::string& out, int frame) {
    const auto column =
        read_particle_block(frame_path(out, "column_collapse_2d_mu_i_small", frame));
    std::vector<double> xy;
    for (vtkIdType i = 0; i < column->GetNumberOfPoints(); ++i) {
        double x[3];
        column->GetPoint(i, x);
        xy.push_back(x[0]);
        xy.push_back(x[1]);
    }
    return xy;
}

TEST(ColumnCollapseMuISmall, WithoutRateEffectIsTheDruckerPragerRunToTheBit) {
    const CaseRun dp =
        run_case_file(kCase, "collapse_mu_i_dp",
                      std::string(kShort) + " --set 'material[0].model=\"drucker_prager\"'");
    ASSERT_EQ(dp.cli.exit_code, 0) << dp.cli.output;
    const CaseRun flat =
        run_case_file(kCase, "collapse_mu_i_flat",
                      std::string(kShort) + " --set 'material[0].mu_i.mu_2=0.3729877825758089'");
    ASSERT_EQ(flat.cli.exit_code, 0) << flat.cli.output;
    const std::vector<double> a = positions(dp.out, 6);
    const std::vector<double> b = positions(flat.out, 6);
    ASSERT_EQ(a.size(), 400u);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i], b[i]) << "coordinate " << i;
    }
    // The column moved by then: the comparison is of a collapse, not of a column at rest.
    const std::vector<double> start = positions(dp.out, 0);
    double moved = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        moved = std::max(moved, std::abs(a[i] - start[i]));
    }
    EXPECT_GT(moved, 0.05);
    // With the case's law the rate is read: the run leaves the Drucker-Prager run (were the
    // step's length not passed to the material, it would be that run to the bit as above).
    const CaseRun law = run_case_file(kCase, "collapse_mu_i_law", kShort);
    ASSERT_EQ(law.cli.exit_code, 0) << law.cli.output;
    EXPECT_TRUE(positions(law.out, 6) != a) << "the mu(I) run is the Drucker-Prager run";
}

TEST(ColumnCollapseMuISmall, KeepsItsEnergyBooksAndComesToRest) {
    const CaseRun run = run_case_file(kCase, "collapse_mu_i");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string summary = read_file(run.out + "/summary.json");
    EXPECT_NE(summary.find("\"mu_i\""), std::string::npos) << "the model that ran";
    const double gained = result_value(summary, "kinetic_energy") +
                          result_value(summary, "internal_energy") +
                          result_value(summary, "contact_energy");
    const double drop = result_value(summary, "gravity_work");
    EXPECT_GT(drop, 0.0);
    EXPECT_NEAR(gained / drop, 1.0, 0.01);
    EXPECT_LT(std::abs(result_value(summary, "energy_balance_error")), 0.01);
    EXPECT_LT(result_value(summary, "heap_final_kinetic_energy_ratio"), 1e-4);
    // The frames' inertial number: a collapse flows in the dense regime 1e-3 < I < 0.1 of GDR
    // MiDi (2004), so while it flows (0.05 s) part of the column lies above 1e-3 and none beyond
    // 0.5, the collisional regime; once at rest (the last frame) every particle lies below 1e-3.
    const auto largest = [&run](int frame) {
        const auto block =
            read_particle_block(frame_path(run.out, "column_collapse_2d_mu_i_small", frame));
        vtkDataArray* inertial = block->GetPointData()->GetArray("inertial_number");
        EXPECT_NE(inertial, nullptr) << "frame " << frame;
        double most = 0.0;
        for (vtkIdType i = 0; inertial != nullptr && i < block->GetNumberOfPoints(); ++i) {
            const double value = inertial->GetTuple1(i);
            most = std::isnan(value) ? most : std::max(most, value); // NaN: p <= 0
        }
        return most;
    };
    EXPECT_GT(largest(1), 1e-3);
    EXPECT_LT(largest(1), 0.5);
    EXPECT_LT(largest(12), 1e-3);
    expect_matches_gold(run.out, "cases/column_collapse_2d/column_collapse_2d_mu_i_small.toml");
}

} // namespace
