#include "support/cli_runner.hpp"
#include "support/test_folder.hpp"

#include <filesystem>
#include <gtest/gtest.h>

namespace {

using namespace grainload::testing;

// Each file in tests/data/bad_cases/ starts with "# expect-line: N" and "# expect-text: ...":
// `grainload check` must exit with code 2 and name the file, that line, and that text.
std::string header_value(const std::string& text, const std::string& key) {
    const auto start = text.find("# " + key + ": ");
    if (start == std::string::npos) {
        return "";
    }
    const auto begin = start + key.size() + 4;
    return text.substr(begin, text.find('\n', begin) - begin);
}

TEST(BadCases, EachGivesExitCodeTwoAndNamesItsLine) {
    const auto directory = std::filesystem::path(source_path("tests/data/bad_cases"));
    int checked = 0;
    for (const auto& entry : std::filesystem::directory_iterator(directory)) {
        const std::string file = entry.path().string();
        const std::string text = read_file(file);
        const std::string line = header_value(text, "expect-line");
        const std::string expected = header_value(text, "expect-text");
        ASSERT_FALSE(line.empty() || expected.empty()) << file << " lacks its expect header";
        const auto result =
            run_cli("check '" + file + "'", grainload::testing::process_folder() + "bad.log");
        EXPECT_EQ(result.exit_code, 2) << file << "\n" << result.output;
        EXPECT_NE(result.output.find(file + ":" + line + ":"), std::string::npos)
            << file << ": expected line " << line << "\n"
            << result.output;
        EXPECT_NE(result.output.find(expected), std::string::npos)
            << file << ": expected \"" << expected << "\"\n"
            << result.output;
        ++checked;
    }
    EXPECT_GE(checked, 15);
}

TEST(BadCases, MalformedCommandLinesAndOverridesExitWithTwo) {
    const std::string good = "'" + source_path("cases/free_fall/free_fall_small.toml") + "'";
    const std::string log = grainload::testing::process_folder() + "cli.log";
    EXPECT_EQ(run_cli("run", log).exit_code, 2);
    EXPECT_EQ(run_cli("simulate " + good, log).exit_code, 2);
    EXPECT_EQ(run_cli("run " + good + " --threads zero", log).exit_code, 2);
    EXPECT_EQ(run_cli("check /nonexistent/case.toml", log).exit_code, 2);
    const auto result = run_cli("check " + good + " --set 'sph.time_step=5'", log);
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.output.find("--set sph.time_step=5"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("expected a time"), std::string::npos) << result.output;
    // Found by tests/fuzz/fuzz_case: an index that is not a number ended in std::stoul's
    // exception, exit code 1.
    for (const char* index : {"x", "", "99999999999999999999999", "-1"}) {
        const auto bad =
            run_cli("check " + good + " --set 'sph.body[" + index + "].spacing=1'", log);
        EXPECT_EQ(bad.exit_code, 2) << index << "\n" << bad.output;
        EXPECT_NE(bad.output.find("is not an index [0], [1], ..."), std::string::npos)
            << bad.output;
    }
    EXPECT_EQ(run_cli("check " + good, log).exit_code, 0);
}

TEST(BadCases, VersionNamesTheRelease) {
    const auto result = run_cli("--version", grainload::testing::process_folder() + "version.log");
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_EQ(result.output.rfind("grainload 0.", 0), 0u) << result.output;
}

} // namespace
