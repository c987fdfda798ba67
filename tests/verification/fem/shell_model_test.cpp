#include "fem/shell_model_reader.hpp"
#include "io/case_table.hpp"
#include "io/output_streams.hpp"
#include "materials/material_case_reader.hpp"
#include "support/test_folder.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace grainload::fem {
namespace {

const std::string kCase =
    std::string(GRAINLOAD_SOURCE_DIR) + "/cases/shell_benchmarks/scordelis_lo.toml";

struct LoadedCase {
    std::unique_ptr<io::CaseDocument> document;
    materials::MaterialLibrary materials;
    std::unique_ptr<ShellModel> model;
};

LoadedCase load(const std::vector<std::string>& overrides = {}) {
    LoadedCase c;
    c.document = io::CaseDocument::from_file(kCase);
    for (const auto& o : overrides) {
        c.document->set(o);
    }
    const io::SceneSettings scene = io::read_scene_settings(*c.document, "scordelis_lo");
    io::CaseTable root = c.document->root();
    c.materials = materials::read_material_library(root);
    c.model = read_shell_model(root, scene, c.materials);
    c.document->reject_unknown_keys();
    return c;
}

// The case file reproduces the Scordelis-Lo benchmark of the C++ set-up (same mesh, same
// result to round-off) and reports it as a result figure with its reference.
TEST(ShellModel, ScordelisLoCaseReachesReference) {
    LoadedCase c = load();
    for (int step = 0; step < 4; ++step) {
        c.model->advance(0.25 * step, 0.25);
        ASSERT_FALSE(c.model->diagnose().has_value()) << *c.model->diagnose();
    }
    std::vector<io::ResultFigure> results;
    c.model->append_results(1.0, results);
    ASSERT_FALSE(results.empty());
    EXPECT_EQ(results[0].unit, "m");
    ASSERT_TRUE(results[0].reference.has_value());
    // 2 % at 16 x 16 on the quarter model: the acceptance tolerance.
    EXPECT_NEAR(results[0].value, *results[0].reference, 0.02 * *results[0].reference);
    EXPECT_NEAR(results[0].value, 0.2991, 5e-4); // the same model as shell_benchmarks_test

    io::Frame frame;
    c.model->append_blocks(frame);
    ASSERT_EQ(frame.blocks.size(), 1u);
    EXPECT_EQ(frame.blocks[0].kind, io::Block::Kind::shell);
    EXPECT_EQ(frame.blocks[0].points.size(), 17u * 17u);
    EXPECT_EQ(frame.blocks[0].cells.size(), 256u);
    // Load steps as time: 4 steps, each converged in one Newton iteration (linear problem).
    ASSERT_EQ(c.model->convergence_log().size(), 4u);
    EXPECT_EQ(c.model->convergence_log().back().report.log.size(), 1u);
}

// The solver that ran is reported in summary.json's results and in the per-step convergence
// CSV (time, increment, iteration, the norms of thesis eqs. 5.2.7-5.2.9, solver).
TEST(ShellModel, ReportsSolverAndWritesConvergenceCsv) {
    LoadedCase c = load();
    const std::string dir = testing::test_folder("fem_csv_test");
    std::filesystem::create_directories(dir);
    io::OutputStreams output(dir);
    c.model->set_output(output);
    for (int step = 0; step < 4; ++step) {
        c.model->advance(0.25 * step, 0.25);
        c.model->write_logs();
    }
    std::vector<io::ResultFigure> results;
    c.model->append_results(1.0, results);
    bool reported = false;
    for (const auto& r : results) {
        if (r.name == "fem_steps_solved_by_cholmod") {
            reported = true;
            EXPECT_EQ(r.source, "CHOLMOD supernodal LLT (METIS)");
            EXPECT_EQ(r.value, 4.0);
        }
    }
    EXPECT_TRUE(reported);
    std::ifstream csv(dir + "/fem_convergence.csv");
    std::string line;
    std::vector<std::string> lines;
    while (std::getline(csv, line)) {
        lines.push_back(line);
    }
    ASSERT_EQ(lines.size(), 5u); // header + one Newton iteration per (linear) step
    EXPECT_EQ(lines[0].rfind("time,increment,iteration,displacement_ratio,force_ratio,", 0), 0u);
    EXPECT_EQ(lines[4].rfind("1,1,1,", 0), 0u) << lines[4];
    EXPECT_NE(lines[4].find("CHOLMOD supernodal"), std::string::npos);
    std::filesystem::remove_all(dir);
}

// A follower pressure from the case file makes the tangent non-symmetric: UMFPACK runs, and
// the results say so.
TEST(ShellModel, FollowerPressureRunsUmfpack) {
    LoadedCase c =
        load({"fem.kinematics=\"total_lagrangian\"", "fem.shell[0].load[0].type=\"pressure\"",
              "fem.shell[0].load[0].value=\"-90 Pa\"", "fem.shell[0].load[0].follower=true"});
    c.model->advance(0.0, 1.0);
    ASSERT_FALSE(c.model->diagnose().has_value()) << *c.model->diagnose();
    std::vector<io::ResultFigure> results;
    c.model->append_results(1.0, results);
    bool umfpack = false;
    for (const auto& r : results) {
        umfpack = umfpack || r.name == "fem_steps_solved_by_umfpack";
    }
    EXPECT_TRUE(umfpack);
}

TEST(ShellModel, CheckpointRestoresState) {
    LoadedCase a = load();
    a.model->advance(0.0, 0.5);
    std::stringstream buffer;
    a.model->write_checkpoint(buffer);
    LoadedCase b = load();
    b.model->read_checkpoint(buffer);
    a.model->advance(0.5, 0.5);
    b.model->advance(0.5, 0.5);
    std::vector<io::ResultFigure> ra, rb;
    a.model->append_results(1.0, ra);
    b.model->append_results(1.0, rb);
    EXPECT_DOUBLE_EQ(ra[0].value, rb[0].value);
}

// The dynamic variant (Newmark trapezoidal) runs from the same file with two overrides; the
// roof period (~0.1 s for this light material) is far above the step.
TEST(ShellModel, DynamicAnalysisAdvances) {
    LoadedCase c = load({"fem.analysis=\"dynamic\"", "fem.time_step=\"1 ms\""});
    EXPECT_DOUBLE_EQ(c.model->stable_time_step(), 1e-3);
    for (int step = 0; step < 5; ++step) {
        c.model->advance(1e-3 * step, 1e-3);
        ASSERT_FALSE(c.model->diagnose().has_value()) << *c.model->diagnose();
    }
    EXPECT_EQ(c.model->convergence_log().size(), 5u);
    std::stringstream buffer;
    c.model->write_checkpoint(buffer);
    LoadedCase d = load({"fem.analysis=\"dynamic\"", "fem.time_step=\"1 ms\""});
    d.model->read_checkpoint(buffer);
    c.model->advance(5e-3, 1e-3);
    d.model->advance(5e-3, 1e-3);
    std::vector<io::ResultFigure> rc, rd;
    c.model->append_results(6e-3, rc);
    d.model->append_results(6e-3, rd);
    EXPECT_DOUBLE_EQ(rc[0].value, rd[0].value);
    EXPECT_GT(rc[0].value, 0.0);
}

// Every case of cases/shell_benchmarks runs as the app's driver would (one advance per output
// interval) and lands within 2 % of each reference it declares: the acceptance tolerance
// for the coarse meshes used there (measured: Scordelis-Lo -1.07 %, hemisphere
// -0.95 %, roll-up -0.74 %, box under pressure +0.03 %).
TEST(ShellModel, EveryBenchmarkCaseMeetsItsReference) {
    for (const char* name : {"scordelis_lo", "pinched_hemisphere", "cantilever_roll_up",
                             "tipping_plate", "box_under_pressure"}) {
        auto document = io::CaseDocument::from_file(std::string(GRAINLOAD_SOURCE_DIR) +
                                                    "/cases/shell_benchmarks/" + name + ".toml");
        const io::SceneSettings scene = io::read_scene_settings(*document, name);
        io::CaseTable root = document->root();
        const double end = scene.end_time;
        const double interval = scene.output_interval;
        const auto materials = materials::read_material_library(root);
        auto model = read_shell_model(root, scene, materials);
        for (double t = 0.0; t < end - 1e-12; t += interval) {
            model->advance(t, std::min(interval, end - t));
            ASSERT_FALSE(model->diagnose().has_value()) << name << ": " << *model->diagnose();
        }
        std::vector<io::ResultFigure> results;
        model->append_results(end, results);
        for (const auto& r : results) {
            if (r.reference) {
                std::printf("%s: %s = %.6g %s (reference %.6g)\n", name, r.name.c_str(), r.value,
                            r.unit.c_str(), *r.reference);
                EXPECT_NEAR(r.value, *r.reference, 0.02 * std::abs(*r.reference)) << name;
            }
        }
    }
}

// HHT-alpha with consistent mass from the case keys.
TEST(ShellModel, HhtWithConsistentMassAdvances) {
    LoadedCase c =
        load({"fem.analysis=\"dynamic\"", "fem.time_step=\"1 ms\"", "fem.integrator=\"hht\"",
              "fem.hht_alpha=-0.1", "fem.mass=\"consistent\""});
    for (int step = 0; step < 3; ++step) {
        c.model->advance(1e-3 * step, 1e-3);
        ASSERT_FALSE(c.model->diagnose().has_value()) << *c.model->diagnose();
    }
    std::vector<io::ResultFigure> results;
    c.model->append_results(3e-3, results);
    EXPECT_GT(results[0].value, 0.0);
}

void expect_case_error(const std::string& override_text, const std::string& fragment) {
    try {
        load({override_text});
        FAIL() << "expected a CaseError for " << override_text;
    } catch (const io::CaseError& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

TEST(ShellModel, BadKeysAreReportedWithTheirPath) {
    expect_case_error("fem.shell[0].boundary[0].dofs=\"ux uq\"", "unknown DOF 'uq'");
    expect_case_error("fem.shell[0].boundary[0].node_set=\"edge\"", "unknown node set 'edge'");
    expect_case_error("fem.shell[0].generator=\"torus\"", "generator");
    expect_case_error("fem.shell[0].radius=\"25 s\"", "radius");
    expect_case_error("fem.shell[0].fold_angle=\"0 deg\"", "fold_angle");
    expect_case_error("fem.shell[0].load[0].time_function=\"nope\"",
                      "no [[fem.time_function]] named 'nope'");
    EXPECT_NO_THROW(load());
}

} // namespace
} // namespace grainload::fem
