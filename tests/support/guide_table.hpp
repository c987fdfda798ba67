#pragma once
// The user guide's key tables read back, to hold them to the declarations.

#include "io/key_spec.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <regex>
#include <span>
#include <sstream>
#include <string>
#include <vector>

namespace grainload::testing {

/// The rows of the markdown table after the line `heading` in the user-guide page `page`
/// (relative to the source tree): key (the first column, in backquotes) -> the default column
/// (the third).
inline std::map<std::string, std::string> guide_table(const std::string& page,
                                                      const std::string& heading) {
    std::ifstream in(std::string(GRAINLOAD_SOURCE_DIR) + "/" + page);
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

/// The table under `heading` lists exactly the keys of `specs`, each with its default
/// ("required" for a key without one).
inline void expect_guide_states(std::span<const io::KeySpec> specs, const std::string& page,
                                const std::string& heading) {
    const auto rows = guide_table(page, heading);
    EXPECT_EQ(rows.size(), specs.size()) << heading;
    for (const io::KeySpec& spec : specs) {
        const auto row = rows.find(std::string(spec.name));
        ASSERT_NE(row, rows.end()) << spec.name << " is not under " << heading;
        EXPECT_EQ(row->second,
                  spec.default_text.empty() ? "required" : std::string(spec.default_text))
            << spec.name;
    }
}

} // namespace grainload::testing
