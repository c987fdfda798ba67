#include "support/case_runner.hpp"
#include "support/frame_reader.hpp"
#include "support/gold_summary.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <gtest/gtest.h>
#include <regex>
#include <vector>
#include <vtkDataArray.h>
#include <vtkPointData.h>

namespace {

using namespace grainload::testing;

struct ColumnState {
    double height_sum = 0.0;        ///< sum of particle y, m
    double front = 0.0;             ///< largest particle x, m
    double top = 0.0;               ///< largest particle y, m
    double speed_squared_sum = 0.0; ///< sum of |v|^2, m^2/s^2
    std::size_t count = 0;
};

ColumnState read_column(const std::string& vtm) {
    const auto column = read_particle_block(vtm);
    ColumnState state;
    vtkDataArray* velocity = column->GetPointData()->GetArray("velocity");
    for (vtkIdType i = 0; i < column->GetNumberOfPoints(); ++i) {
        double x[3];
        column->GetPoint(i, x);
        const double* v = velocity->GetTuple3(i);
        state.speed_squared_sum += v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        state.height_sum += x[1];
        state.front = std::max(state.front, x[0]);
        state.top = std::max(state.top, x[1]);
    }
    state.count = static_cast<std::size_t>(column->GetNumberOfPoints());
    return state;
}

// The CI version of column_collapse_2d (20 x 10 particles, 0.6 s). The walls are static, so they
// do no work: the potential energy the column loses must reappear as kinetic plus internal
// energy (stress power, plastic and viscous dissipation, and the heat of wall friction and of
// the contact dashpot, which wall contact books into the particles' internal energy) plus the
// elastic energy stored in the floor's contact potential (summary "contact_energy"). What the
// balance leaves out is leapfrog's O(dt^2) energy error, below 1 %. Measured: 0.09 % (2.6 %
// missing when the contact's stored energy is left out). The run's own books
// ("gravity_work", sum m g . v dt over the drifts) must match the potential drop read from
// the first and last frames. The heap must also come
// to rest (the collapse cases' criterion: kinetic energy below 1e-4 of its peak): on a frictionless
// floor the back wall's thrust keeps the heap sliding for ever
// (docs/validation/column_collapse_2d.md).
TEST(ColumnCollapseSmall, LosesPotentialEnergyToHeatAndComesToRest) {
    const CaseRun run = run_case_file("cases/column_collapse_2d/column_collapse_2d_small.toml",
                                      "column_collapse_small");
    ASSERT_EQ(run.cli.exit_code, 0) << run.cli.output;
    const std::string& out = run.out;
    std::vector<ColumnState> frames;
    for (int frame = 0; frame <= 12; ++frame) {
        frames.push_back(read_column(frame_path(out, "column_collapse_2d_small", frame)));
    }
    const ColumnState& start = frames.front();
    const ColumnState& end = frames.back();
    ASSERT_EQ(start.count, 200u);
    const double particle_mass = 2040.0 * 0.01 * 0.01; // rho dx^2, kg per metre of depth
    const double potential_drop = particle_mass * 9.81 * (start.height_sum - end.height_sum);
    const std::string summary = read_file(out + "/summary.json");
    const double gained = result_value(summary, "kinetic_energy") +
                          result_value(summary, "internal_energy") +
                          result_value(summary, "contact_energy");
    EXPECT_GT(potential_drop, 0.0);
    EXPECT_NEAR(gained / potential_drop, 1.0, 0.01)
        << "potential energy lost " << potential_drop << " J/m, gained " << gained << " J/m";
    // The frames store positions in double precision; the two sums differ by round-off only.
    EXPECT_NEAR(result_value(summary, "gravity_work"), potential_drop, 1e-9 * potential_drop);
    EXPECT_LT(std::abs(result_value(summary, "energy_balance_error")), 0.01);
    // Particle-steps per second count the material: the 20 x 10 grains, not the wall particles.
    EXPECT_NE(summary.find("\"material_points\": 200,"), std::string::npos) << summary;
    // The column slumps: its front runs out and its top comes down.
    EXPECT_GT(end.front, start.front + 0.01);
    EXPECT_LT(end.top, start.top);
    double peak = 0.0;
    for (const ColumnState& frame : frames) {
        peak = std::max(peak, frame.speed_squared_sum);
    }
    EXPECT_LT(end.speed_squared_sum, 1e-4 * peak);
    expect_matches_gold(out, "cases/column_collapse_2d/column_collapse_2d_small.toml");
}

// A deforming run (plasticity, wall friction and dashpot, Verlet list, gradient correction)
// continued from its checkpoint must end bit for bit where the uninterrupted run ends: the
// checkpoint carries the step's accelerations (computed from the mid-step velocity) and the
// positions the neighbour list was built from, so nothing is recomputed differently. The split
// at 0.15 s, 2e-17 s short of the output instant 3 x 0.05 s, also checks that an end time is
// snapped to the instant it means.
TEST(ColumnCollapseSmall, RestartOfADeformingRunReproducesTheUninterruptedRun) {
    const std::string base = test_folder("column_collapse_restart");
    const std::string kase =
        "'" + source_path("cases/column_collapse_2d/column_collapse_2d_small.toml") +
        "' --set 'sph.kernel_gradient_correction=true' --set 'case.end_time=0.3 s'";
    std::filesystem::remove_all(base + "_whole");
    std::filesystem::remove_all(base + "_split");
    ASSERT_EQ(run_cli("run " + kase + " --out '" + base + "_whole'", base + ".log").exit_code, 0);
    const auto first = run_cli(
        "run " + kase + " --set 'case.end_time=0.15 s' --out '" + base + "_split'", base + ".log");
    ASSERT_EQ(first.exit_code, 0) << first.output;
    const auto second = run_cli("run " + kase + " --out '" + base + "_split' --restart '" + base +
                                    "_split/checkpoint.bin'",
                                base + ".log");
    ASSERT_EQ(second.exit_code, 0) << second.output;
    const std::string frame = "/frames/column_collapse_2d_small_000006.vtm";
    const auto whole = read_particle_block(base + "_whole" + frame);
    const auto split = read_particle_block(base + "_split" + frame);
    ASSERT_EQ(whole->GetNumberOfPoints(), split->GetNumberOfPoints());
    for (vtkIdType i = 0; i < whole->GetNumberOfPoints(); ++i) {
        double a[3];
        double b[3];
        whole->GetPoint(i, a);
        split->GetPoint(i, b);
        EXPECT_TRUE(a[0] == b[0] && a[1] == b[1]) << "particle " << i;
    }
}

} // namespace
