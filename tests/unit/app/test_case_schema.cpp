// The case file's declared schema: every table documented as declared, each key declared once.

#include "app/case_schema.hpp"
#include "support/guide_table.hpp"

#include <gtest/gtest.h>
#include <set>
#include <string>

namespace grainload::app {
namespace {

// The user guide's table for every declared table (or part of one) lists exactly the declared
// keys with their declared defaults: the guide cannot drift from the code (MOOSE validParams).
TEST(CaseSchema, TheUserGuideStatesEveryDeclaredTableWithItsDefaults) {
    ASSERT_FALSE(case_schema().empty());
    for (const io::KeyTable& table : case_schema()) {
        SCOPED_TRACE(std::string(table.name));
        ASSERT_FALSE(table.guide_page.empty());
        ASSERT_FALSE(table.doc.empty());
        if (!table.user_keys) {
            testing::expect_guide_states(table.keys, std::string(table.guide_page),
                                         std::string(table.guide_heading));
        }
    }
}

// A key is declared once in its table, over all of the table's parts, so one default holds.
TEST(CaseSchema, EveryKeyIsDeclaredOnceInItsTable) {
    std::set<std::string> seen;
    for (const io::KeyTable& table : case_schema()) {
        for (const io::KeySpec& key : table.keys) {
            const std::string full = std::string(table.name) + "." + std::string(key.name);
            EXPECT_TRUE(seen.insert(full).second) << full << " is declared twice";
            EXPECT_FALSE(key.type.empty()) << full;
            EXPECT_FALSE(key.doc.empty()) << full;
        }
    }
}

// A key's path names its table without indices; root keys lie in no table.
TEST(CaseSchema, AKeysPathNamesItsTable) {
    EXPECT_EQ(io::table_of_key("sph.body[0].shape.cut[12].normal"), "sph.body.shape.cut");
    EXPECT_EQ(io::table_of_key("case.end_time"), "case");
    EXPECT_EQ(io::table_of_key("material[3].mu_i.i0"), "material.mu_i");
    EXPECT_EQ(io::table_of_key("title"), "");
}

} // namespace
} // namespace grainload::app
