#include "support/cli_runner.hpp"
#include "support/frame_reader.hpp"
#include "support/gold_summary.hpp"
#include "support/test_folder.hpp"

#include <Eigen/Core>
#include <filesystem>
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>

namespace {

using namespace grainload::testing;
using Vec3 = Eigen::Vector3d;

const std::string kCase = "'" + source_path("cases/free_fall/free_fall_small.toml") + "'";

struct Cloud {
    std::vector<Vec3> position;
    std::vector<Vec3> velocity;
};

Cloud read_frame(const std::string& vtm) {
    const auto block = read_particle_block(vtm);
    Cloud cloud;
    vtkDataArray* velocity = block->GetPointData()->GetArray("velocity");
    for (vtkIdType i = 0; i < block->GetNumberOfPoints(); ++i) {
        double x[3];
        block->GetPoint(i, x);
        cloud.position.emplace_back(x[0], x[1], x[2]);
        cloud.velocity.emplace_back(velocity->GetTuple3(i)[0], velocity->GetTuple3(i)[1],
                                    velocity->GetTuple3(i)[2]);
    }
    return cloud;
}

std::string out_dir(const std::string& name) {
    const std::string directory = test_folder(name);
    std::filesystem::remove_all(directory);
    return directory;
}

// Velocity Verlet integrates a constant acceleration exactly, so the particles must sit on
// x0 + v0 t + g t^2/2 up to round-off: positions ~1 m, 200 steps, 1e-12 m is ~1e3 ulp.
TEST(FreeFall, ParticlesFollowTheBallisticPathToRoundOff) {
    const std::string out = out_dir("free_fall");
    const auto result = run_cli("run " + kCase + " --out '" + out + "'", out + ".log");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const Cloud start = read_frame(frame_path(out, "free_fall_small", 0));
    const Cloud end = read_frame(frame_path(out, "free_fall_small", 20));
    ASSERT_EQ(start.position.size(), 4u * 4u * 8u);
    const double t = 0.2;
    const Vec3 g(0.0, 0.0, -9.81);
    for (std::size_t i = 0; i < start.position.size(); ++i) {
        const Vec3 exact = start.position[i] + t * start.velocity[i] + 0.5 * t * t * g;
        EXPECT_LT((end.position[i] - exact).norm(), 1e-12) << "particle " << i;
        EXPECT_LT((end.velocity[i] - (start.velocity[i] + t * g)).norm(), 1e-12);
    }
    const std::string summary = read_file(out + "/summary.json");
    EXPECT_NE(summary.find("\"status\": \"completed\""), std::string::npos) << summary;
    EXPECT_NE(summary.find("\"centre_height\": {\"value\""), std::string::npos) << summary;
    EXPECT_NE(read_file(out + "/free_fall_small.pvd").find("timestep=\"0.2\""), std::string::npos);
    EXPECT_NE(read_file(out + "/log.txt").find("particle-steps/s"), std::string::npos);
    expect_matches_gold(out, "cases/free_fall/free_fall_small.toml");
}

// A run continued from its checkpoint must end bit for bit where the uninterrupted run ends.
TEST(FreeFall, RestartFromCheckpointReproducesTheUninterruptedRun) {
    const std::string whole = out_dir("whole");
    ASSERT_EQ(run_cli("run " + kCase + " --out '" + whole + "'", whole + ".log").exit_code, 0);
    const std::string split = out_dir("split");
    const auto first = run_cli(
        "run " + kCase + " --set 'case.end_time=0.1 s' --out '" + split + "'", split + ".log");
    ASSERT_EQ(first.exit_code, 0) << first.output;
    const auto second =
        run_cli("run " + kCase + " --out '" + split + "' --restart '" + split + "/checkpoint.bin'",
                split + ".log");
    ASSERT_EQ(second.exit_code, 0) << second.output;
    const Cloud a = read_frame(frame_path(whole, "free_fall_small", 20));
    const Cloud b = read_frame(frame_path(split, "free_fall_small", 20));
    ASSERT_EQ(a.position.size(), b.position.size());
    for (std::size_t i = 0; i < a.position.size(); ++i) {
        EXPECT_EQ(a.position[i], b.position[i]) << "particle " << i;
    }
    EXPECT_EQ(read_file(whole + "/free_fall_small.pvd"), read_file(split + "/free_fall_small.pvd"));
}

// The same block read from an LS-DYNA deck (tests/data/keyword/free_fall_block.k, mm-t-s,
// written by make_free_fall_block.py): the particles start where the box generator puts them
// (mm to m and the generator's min + spacing (i + 1/2) differ by a rounding, below 1e-15 m
// at 1.2 m) with the deck's masses accepted, and fall the same way (1e-12 m as above).
TEST(FreeFall, BodyFromAnLsDynaDeckMatchesTheBoxBody) {
    const std::string box = out_dir("box_body");
    ASSERT_EQ(run_cli("run " + kCase + " --out '" + box + "'", box + ".log").exit_code, 0);
    const std::string deck = out_dir("deck_body");
    const auto result = run_cli("run '" + source_path("tests/data/keyword/free_fall_lsdyna.toml") +
                                    "' --out '" + deck + "'",
                                deck + ".log");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    for (const char* frame : {"000000", "000020"}) {
        const Cloud a = read_frame(box + "/frames/free_fall_small_" + frame + ".vtm");
        const Cloud b = read_frame(deck + "/frames/free_fall_lsdyna_" + frame + ".vtm");
        ASSERT_EQ(a.position.size(), b.position.size());
        for (std::size_t i = 0; i < a.position.size(); ++i) {
            EXPECT_LT((a.position[i] - b.position[i]).norm(),
                      std::string(frame) == "000000" ? 1e-15 : 1e-12)
                << "particle " << i << " at frame " << frame;
        }
    }
}

// Gravity of 1e308 m/s^2 overflows the position near t = 1.4 s (x = g t^2/2 > 1.8e308): the run
// must stop with a diagnosis, exit code 3, and keep a readable last good frame and its checkpoint.
TEST(FreeFall, UnstableRunStopsWithDiagnosisAndKeepsLastGoodFrame) {
    const std::string out = out_dir("unstable");
    const auto result =
        run_cli("run " + kCase +
                    " --set 'case.gravity=0 0 -1e308 m/s^2'"
                    " --set 'case.end_time=5 s' --set 'case.output_interval=1 s' --out '" +
                    out + "'",
                out + ".log");
    EXPECT_EQ(result.exit_code, 3) << result.output;
    EXPECT_NE(result.output.find("non-finite or non-physical"), std::string::npos) << result.output;
    const std::string summary = read_file(out + "/summary.json");
    EXPECT_NE(summary.find("\"status\": \"unstable\""), std::string::npos) << summary;
    const auto last = result.output.substr(result.output.find("last good frame: ") + 17);
    const Cloud cloud = read_frame(last.substr(0, last.find('\n')));
    for (const Vec3& x : cloud.position) {
        EXPECT_TRUE(x.allFinite());
    }
    EXPECT_TRUE(std::filesystem::exists(out + "/checkpoint.bin"));
}

} // namespace
