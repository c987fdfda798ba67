#include "support/cli_runner.hpp"
#include "support/test_folder.hpp"

#include <filesystem>
#include <gtest/gtest.h>
#include <vector>

namespace {

using namespace grainload::testing;

// Each file in tests/data/scene_warnings/ is a scene `grainload check` accepts (exit 0) with
// what it must say in its header: "# expect-warning-once: TEXT" (TEXT in exactly one line of the
// output, a "grainload: warning:" line) and "# expect-absent: TEXT" (nowhere in the output).
std::vector<std::string> header_values(const std::string& text, const std::string& key) {
    std::vector<std::string> values;
    const std::string marker = "# " + key + ": ";
    for (auto start = text.find(marker); start != std::string::npos;
         start = text.find(marker, start + 1)) {
        const auto begin = start + marker.size();
        values.push_back(text.substr(begin, text.find('\n', begin) - begin));
    }
    return values;
}

/// The lines of `output` that hold `text`.
std::vector<std::string> lines_with(const std::string& output, const std::string& text) {
    std::vector<std::string> found;
    std::size_t begin = 0;
    while (begin < output.size()) {
        const auto end = std::min(output.find('\n', begin), output.size());
        const std::string line = output.substr(begin, end - begin);
        if (line.find(text) != std::string::npos) {
            found.push_back(line);
        }
        begin = end + 1;
    }
    return found;
}

TEST(SceneWarnings, EachIsSaidOnceAndTheScenePasses) {
    const auto directory = std::filesystem::path(source_path("tests/data/scene_warnings"));
    int checked = 0;
    for (const auto& entry : std::filesystem::directory_iterator(directory)) {
        const std::string file = entry.path().string();
        const std::string text = read_file(file);
        const auto once = header_values(text, "expect-warning-once");
        const auto absent = header_values(text, "expect-absent");
        ASSERT_FALSE(once.empty() && absent.empty()) << file << " lacks its expect header";
        const auto result = run_cli("check '" + file + "'", process_folder() + "warnings.log");
        EXPECT_EQ(result.exit_code, 0) << file << "\n" << result.output;
        for (const std::string& expected : once) {
            const auto lines = lines_with(result.output, expected);
            EXPECT_EQ(lines.size(), 1u) << file << ": expected \"" << expected << "\" once\n"
                                        << result.output;
            for (const std::string& line : lines) {
                EXPECT_EQ(line.rfind("grainload: warning: ", 0), 0u) << line;
            }
        }
        for (const std::string& unexpected : absent) {
            EXPECT_EQ(result.output.find(unexpected), std::string::npos)
                << file << ": did not expect \"" << unexpected << "\"\n"
                << result.output;
        }
        ++checked;
    }
    EXPECT_GE(checked, 5);
}

// The slot silo's discharge: a seed row one particle thick that its source fills, a gate in the
// floor removed at 2 s and a sink with an outlet below it, all reached by the sand. Its check
// says nothing to act on.
TEST(SceneWarnings, TheSiloDischargeIsCheckedWithoutWarnings) {
    const auto result =
        run_cli("check '" + source_path("cases/silo/silo_discharge_small.toml") + "'",
                process_folder() + "silo.log");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(result.output.find("warning"), std::string::npos) << result.output;
}

} // namespace
