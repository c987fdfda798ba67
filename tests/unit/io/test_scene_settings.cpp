#include "io/case_table.hpp"
#include "io/scene_settings.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <regex>
#include <sstream>

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

/// The rows of the markdown table that follows `heading` in `file`: key -> default column.
std::map<std::string, std::string> guide_table(const std::string& file, const std::string& heading,
                                               int default_column) {
    std::ifstream in(std::string(GRAINLOAD_SOURCE_DIR) + "/" + file);
    std::string line;
    while (std::getline(in, line) && line != heading) {
    }
    std::map<std::string, std::string> rows;
    bool in_table = false;
    while (std::getline(in, line)) {
        if (line.rfind("|", 0) != 0) {
            if (in_table) {
                break;
            }
            continue;
        }
        in_table = true;
        std::vector<std::string> cells;
        std::stringstream row(line.substr(1));
        std::string cell;
        while (std::getline(row, cell, '|')) {
            cells.push_back(std::regex_replace(cell, std::regex("^\\s+|\\s+$"), ""));
        }
        if (cells.size() > static_cast<std::size_t>(default_column) && cells[0].size() > 2 &&
            cells[0].front() == '`') {
            rows[cells[0].substr(1, cells[0].size() - 2)] =
                cells[static_cast<std::size_t>(default_column)];
        }
    }
    return rows;
}

// The user guide's [case] table lists exactly the declared keys with their declared defaults,
// so the guide cannot drift from the code (MOOSE-style validParams).
TEST(SceneSettings, UserGuideStatesEveryCaseKeyWithItsDefault) {
    const auto rows = guide_table("docs/user-guide.md", "## `[case]`", 2);
    EXPECT_EQ(rows.size(), kCaseKeys.size());
    for (const KeySpec& spec : kCaseKeys) {
        const auto row = rows.find(std::string(spec.name));
        ASSERT_NE(row, rows.end()) << spec.name << " is not in the user guide";
        const std::string expected =
            spec.default_text.empty() ? "required" : std::string(spec.default_text);
        EXPECT_EQ(row->second, expected) << spec.name;
    }
}

} // namespace
} // namespace grainload::io
