#include "io/case_table.hpp"
#include "io/scene_settings.hpp"

#include <filesystem>
#include <gtest/gtest.h>

namespace grainload::io {
namespace {

SceneSettings read(const std::string& text) {
    auto document = CaseDocument::from_string(text, "scene.toml");
    return read_scene_settings(*document, "scene");
}

// One default for gravity, read once for every module: -9.81 m/s^2 along the scene's up axis
// (z in 3D, y in plane strain, whose plane is x-y).
TEST(SceneSettings, GravityDefaultsAlongTheUpAxis) {
    const SceneSettings three = read("[case]\nend_time = \"1 s\"\n");
    EXPECT_EQ(three.gravity, Vec3(0.0, 0.0, -9.81));
    EXPECT_EQ(three.name, "scene");
    EXPECT_DOUBLE_EQ(three.output_interval, 0.05);
    const SceneSettings two = read("[case]\nend_time = \"1 s\"\ndimension = 2\n");
    EXPECT_EQ(two.gravity, Vec3(0.0, -9.81, 0.0));
    const SceneSettings given =
        read("[case]\nend_time = \"1 s\"\ndimension = 2\ngravity = \"1 -2 m/s^2\"\n");
    EXPECT_EQ(given.gravity, Vec3(1.0, -2.0, 0.0));
}

// 0.2 s at 1e-12 s is 2e11 output intervals: `grainload check` counted them one by one (over
// 20 s; seen when the case reader's fuzz harness was made to reach the cost estimate) and a run
// would write as many frames.
// 1e6 intervals are the most (io::kMostOutputIntervals): exactly 1e6 is read, 1e6 + 1 is
// refused, naming the key and the shortest interval, 0.2 s / 1e6 = 2e-7 s.
TEST(SceneSettings, MoreThanAMillionOutputIntervalsAreRefused) {
    EXPECT_DOUBLE_EQ(
        read("[case]\nend_time = \"1 s\"\noutput_interval = \"1 us\"\n").output_interval, 1e-6);
    try {
        read("[case]\nend_time = \"0.2 s\"\noutput_interval = \"1e-12 s\"\n");
        FAIL() << "2e11 output intervals were accepted";
    } catch (const CaseError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("key 'case.output_interval'"), std::string::npos) << message;
        EXPECT_NE(message.find("an interval of at least 2e-07 s"), std::string::npos) << message;
    }
    EXPECT_THROW(read("[case]\nend_time = \"1.000001 s\"\noutput_interval = \"1 us\"\n"),
                 CaseError);
}

} // namespace
} // namespace grainload::io
