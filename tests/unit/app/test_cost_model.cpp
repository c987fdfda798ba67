// The cost model of `grainload check` (app/cost_estimate.hpp) on loaded CI scenes, with
// calibrations that isolate one cost each, so that what the model charges for it is exact
// arithmetic: the step's fixed cost once per SPH step on any thread count, the formulation's
// factor on the particles' costs, and nothing for particles in free flight.

#include "app/cost_estimate.hpp"
#include "app/resources/calibration.hpp"
#include "app/scene.hpp"
#include "support/cli_runner.hpp"

#include <gtest/gtest.h>

namespace {

using namespace grainload;

/// A calibration of zero costs: a test sets the one it checks.
app::Calibration nothing() {
    app::Calibration c;
    c.seconds_per_entry_2d = c.seconds_per_body_2d = c.seconds_per_wall_2d = 0.0;
    c.seconds_per_contact_entry_2d = 0.0;
    c.seconds_per_entry_3d = c.seconds_per_body_3d = c.seconds_per_wall_3d = 0.0;
    c.seconds_per_contact_entry_3d = 0.0;
    c.seconds_per_step_2d = c.seconds_per_step_3d = 0.0;
    c.seconds_per_frame = c.seconds_per_frame_point = 0.0;
    return c;
}

// The step's fixed cost (the parallel loops' entries, the books) does not divide among threads:
// the CI 2D collapse's estimate is that cost times its SPH steps on one thread and on two,
// whatever the calibrated speed-up.
TEST(CostModel, AStepsFixedCostIsPaidOncePerStepOnAnyThreadCount) {
    const auto scene = app::Scene::load(
        grainload::testing::source_path("cases/column_collapse_2d/column_collapse_2d_small.toml"),
        {});
    app::Calibration c = nothing();
    c.seconds_per_step_2d = 1e-3;
    c.threads_measured = 2;
    c.speedup = 1.8;
    for (const int threads : {1, 2}) {
        const app::CostEstimate e = app::estimate_cost(*scene, threads, c);
        EXPECT_GT(e.sph_steps, 9000.0);
        EXPECT_NEAR(e.wall_time_s, 1e-3 * e.sph_steps, 1e-12 * e.sph_steps) << threads;
    }
}

// The kernel-gradient correction and the total Lagrangian formulation are calibrated as factors
// on a block's step: the collapse (no correction) costs the body particles' cost, with the
// correction switched on that times the factor, exactly.
TEST(CostModel, TheKernelGradientCorrectionCostsItsCalibratedFactor) {
    const std::string file =
        grainload::testing::source_path("cases/column_collapse_2d/column_collapse_2d_small.toml");
    app::Calibration c = nothing();
    c.seconds_per_body_2d = 1e-6;
    c.seconds_per_entry_2d = 1e-8;
    c.corrected_factor_2d = 3.0;
    c.total_lagrangian_factor_2d = 0.5;
    const auto plain = app::estimate_cost(*app::Scene::load(file, {}), 1, c);
    const auto corrected =
        app::estimate_cost(*app::Scene::load(file, {"sph.kernel_gradient_correction=true"}), 1, c);
    const auto total =
        app::estimate_cost(*app::Scene::load(file, {"sph.kernel_gradient_correction=true",
                                                    "sph.formulation=\"total_lagrangian\""}),
                           1, c);
    ASSERT_GT(plain.sph_seconds, 0.0);
    EXPECT_NEAR(corrected.sph_seconds / plain.sph_seconds, 3.0, 1e-12);
    EXPECT_NEAR(total.sph_seconds / plain.sph_seconds, 0.5, 1e-12);
}

// Particles in free flight (interactions = false) have no neighbours, stresses or contacts:
// the full free fall costs its frames alone, 2000 particles in each of its 11 output instants.
TEST(CostModel, ParticlesInFreeFlightCostTheirFramesAlone) {
    const auto scene =
        app::Scene::load(grainload::testing::source_path("cases/free_fall/free_fall.toml"), {});
    app::Calibration c = nothing();
    c.seconds_per_body_3d = 1e-3;
    c.seconds_per_step_3d = 1e-3;
    c.seconds_per_frame_point = 1e-6;
    const app::CostEstimate e = app::estimate_cost(*scene, 1, c);
    EXPECT_EQ(e.sph_seconds, 0.0);
    EXPECT_NEAR(e.wall_time_s, 11.0 * 2000.0 * 1e-6, 1e-12);
}

} // namespace
