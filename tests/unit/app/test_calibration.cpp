// The calibration `grainload check` estimates with (app/resources/calibration.hpp): a file whose
// speed-up of several threads is below 1 contradicts itself (more threads cannot be slower on a
// quiet machine; the measurement met a busy one) and its speed-up is discarded, the costs kept; the
// description says which file, how busy the machine was, and what was discarded.

#include "app/resources/calibration.hpp"
#include "support/test_folder.hpp"

#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>

namespace {

using grainload::app::Calibration;
using grainload::app::describe_calibration;
using grainload::app::load_calibration;

/// Loads a calibration file of the given speed-up and load through $GRAINLOAD_CALIBRATION.
Calibration load_written(const std::string& name, double speedup, double others, bool quiet) {
    const std::string path = grainload::testing::test_folder(name);
    std::ofstream(path) << "{\n  \"date\": \"2026-12-10 09:00\",\n"
                        << "  \"seconds_per_body_3d\": 7e-7,\n"
                        << "  \"shell_factorisation_seconds\": 0.4,\n"
                        << "  \"threads_measured\": 2,\n  \"speedup\": " << speedup << ",\n"
                        << "  \"others_load\": " << others << ",\n"
                        << "  \"quiet\": " << (quiet ? "true" : "false") << "\n}\n";
    setenv("GRAINLOAD_CALIBRATION", path.c_str(), 1);
    Calibration c = load_calibration();
    unsetenv("GRAINLOAD_CALIBRATION");
    return c;
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

} // namespace
