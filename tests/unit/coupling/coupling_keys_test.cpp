#include "coupling/coupling_case_reader.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <regex>
#include <sstream>

namespace grainload::coupling {
namespace {

/// The rows of the markdown table after `heading` in docs/user-guide/coupling.md: key ->
/// default column (the third).
std::map<std::string, std::string> guide_table(const std::string& heading) {
    std::ifstream in(std::string(GRAINLOAD_SOURCE_DIR) + "/docs/user-guide/coupling.md");
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
        if (cells.size() > 2 && cells[0].size() > 2 && cells[0].front() == '`') {
            rows[cells[0].substr(1, cells[0].size() - 2)] = cells[2];
        }
    }
    return rows;
}

template <std::size_t N>
void expect_guide_states(const std::array<io::KeySpec, N>& specs, const std::string& heading) {
    const auto rows = guide_table(heading);
    EXPECT_EQ(rows.size(), specs.size()) << heading;
    for (const io::KeySpec& spec : specs) {
        const auto row = rows.find(std::string(spec.name));
        ASSERT_NE(row, rows.end()) << spec.name << " is not under " << heading;
        EXPECT_EQ(row->second,
                  spec.default_text.empty() ? "required" : std::string(spec.default_text))
            << spec.name;
    }
}

// The user guide's [coupling] tables list exactly the declared keys with their defaults.
TEST(CouplingKeys, UserGuideStatesEveryKeyWithItsDefault) {
    expect_guide_states(kCouplingKeys, "## `[coupling]`");
    expect_guide_states(kInterfaceKeys, "## `[[coupling.interface]]`");
}

} // namespace
} // namespace grainload::coupling
