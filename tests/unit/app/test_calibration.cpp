// The calibration `grainload check` estimates with (app/resources/calibration.hpp): a file whose
// speed-up of several threads is below 1 contradicts itself (more threads cannot be slower on a
// quiet machine; the measurement met a busy one) and its speed-up is discarded, the costs kept; the
// description says which file, how busy the machine was, and what was discarded. Costs the bench
// could not measure (its runs of the grainload executable failed) keep their built-in figures.

#include "app/resources/calibration.hpp"
#include "support/test_folder.hpp"

#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>

namespace {

using grainload::app::Calibration;
using grainload::app::describe_calibration;
using grainload::app::load_calibration;

/// Loads a calibration file of the text `json` through $GRAINLOAD_CALIBRATION.
Calibration load_text(const std::string& name, const std::string& json) {
    const std::string path = grainload::testing::test_folder(name);
    std::ofstream(path) << json;
    setenv("GRAINLOAD_CALIBRATION", path.c_str(), 1);
    Calibration c = load_calibration();
    unsetenv("GRAINLOAD_CALIBRATION");
    return c;
}

/// Loads a calibration file of the given speed-up and load.
Calibration load_written(const std::string& name, double speedup, double others, bool quiet) {
    return load_text(name, "{\n  \"date\": \"2026-12-10 09:00\",\n"
                           "  \"seconds_per_body_3d\": 7e-7,\n"
                           "  \"shell_factorisation_seconds\": 0.4,\n"
                           "  \"threads_measured\": 2,\n  \"speedup\": " +
                               std::to_string(speedup) +
                               ",\n  \"others_load\": " + std::to_string(others) +
                               ",\n  \"quiet\": " + (quiet ? "true" : "false") + "\n}\n");
}

TEST(Calibration, ASpeedupBelowOneIsDiscardedAndSaidSo) {
    // The build's own measurement of 55 min on two threads against 47 on one: 0.85.
    const Calibration c = load_written("calibration_slower.json", 0.85, 1.6, false);
    EXPECT_EQ(c.threads_measured, 1);
    EXPECT_EQ(c.speedup, 1.0);
    // The costs it measured in CPU time stay.
    EXPECT_EQ(c.seconds_per_body_3d, 7e-7);
    EXPECT_EQ(c.shell_factorisation_seconds, 0.4);
    const std::string text = describe_calibration(c);
    EXPECT_NE(text.find("calibration_slower.json (2026-12-10 09:00)"), std::string::npos) << text;
    EXPECT_NE(text.find("under load, not quiet (other processes used 1.60 cores)"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("speed-up of 2 threads, 0.85, is below 1 and contradicts itself: "
                        "discarded"),
              std::string::npos)
        << text;
}

TEST(Calibration, AQuietSpeedupIsKept) {
    const Calibration c = load_written("calibration_quiet.json", 1.84, 0.05, true);
    EXPECT_EQ(c.threads_measured, 2);
    EXPECT_EQ(c.speedup, 1.84);
    EXPECT_TRUE(c.note.empty());
    const std::string text = describe_calibration(c);
    EXPECT_NE(
        text.find("on a quiet machine (other processes used 0.05 cores); 2 threads 1.84x one"),
        std::string::npos)
        << text;
}

/// What a quiet calibration whose runs of the grainload executable failed (a build relinking it
/// meanwhile) says: the costs it could not measure keep their built-in figures, never zero
/// (a zero frame or step cost estimates free output and free steps), and the description says
/// the calibration is incomplete although the machine was quiet.
void expect_incomplete(const Calibration& c) {
    const Calibration built_in;
    EXPECT_EQ(c.seconds_per_frame, built_in.seconds_per_frame);
    EXPECT_EQ(c.seconds_per_frame_point, built_in.seconds_per_frame_point);
    EXPECT_EQ(c.seconds_per_step_2d, built_in.seconds_per_step_2d);
    EXPECT_EQ(c.seconds_per_step_3d, built_in.seconds_per_step_3d);
    EXPECT_EQ(c.dem_seconds_per_step, built_in.dem_seconds_per_step);
    EXPECT_EQ(c.dem_seconds_per_grain_step, built_in.dem_seconds_per_grain_step);
    EXPECT_EQ(c.seconds_per_body_3d, 7e-7); // what it measured in-process stays
    const std::string text = describe_calibration(c);
    EXPECT_NE(text.find("on a quiet machine (other processes used 0.05 cores)"), std::string::npos)
        << text;
    EXPECT_NE(text.find("incomplete: a step's fixed cost, the DEM's costs, an output instant's "
                        "cost not measured (the bench could not run the grainload executable), "
                        "the built-in figures used"),
              std::string::npos)
        << text;
}

TEST(Calibration, CostsTheBenchCouldNotMeasureKeepTheirBuiltInFiguresAndSaySo) {
    // As bench/sph_throughput --calibrate writes it: the pairs it could not measure absent and
    // listed.
    expect_incomplete(load_text("calibration_listed.json",
                                "{\"date\": \"2026-12-10 09:00\", \"seconds_per_body_3d\": 7e-7,"
                                " \"not_measured\": [\"seconds_per_step_2d\", "
                                "\"seconds_per_step_3d\", \"dem_seconds_per_step\", "
                                "\"dem_seconds_per_grain_step\", \"seconds_per_frame\", "
                                "\"seconds_per_frame_point\"], \"others_load\": 0.05, "
                                "\"quiet\": true}"));
}

TEST(Calibration, ZerosOfAnEarlierBenchWhoseRunsFailedAreNotTakenForCosts) {
    // An earlier bench wrote zeros for what its failed runs did not measure, and "quiet".
    expect_incomplete(load_text(
        "calibration_zeros.json",
        "{\"source\": \"bench/sph_throughput --calibrate\", \"date\": \"2026-12-10 09:00\", "
        "\"seconds_per_body_3d\": 7e-7, "
        "\"seconds_per_step_2d\": 0, \"seconds_per_step_3d\": 0, \"dem_seconds_per_step\": 0, "
        "\"dem_seconds_per_grain_step\": 0, \"seconds_per_frame\": 0, "
        "\"seconds_per_frame_point\": 0, \"others_load\": 0.05, \"quiet\": true}"));
}

} // namespace
