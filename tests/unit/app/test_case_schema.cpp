// The case file's declared schema: every table documented as declared, each key declared once.

#include "app/case_schema.hpp"
#include "app/scene.hpp"
#include "io/case_error.hpp"
#include "io/units.hpp"
#include "support/cli_runner.hpp"
#include "support/guide_table.hpp"
#include "support/test_folder.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

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

/// Calls `check(table, key, text)` for every declared key, `text` its default as the user writes
/// it (the guide's backquotes and quotes removed); returns how many calls returned true.
template <class Check> int count_defaults(Check check) {
    int checked = 0;
    for (const io::KeyTable& table : case_schema()) {
        for (const io::KeySpec& key : table.keys) {
            std::string text(key.default_text);
            std::erase_if(text, [](char c) { return c == '`' || c == '"'; });
            checked += check(table, key, text) ? 1 : 0;
        }
    }
    return checked;
}

// Readers take a default from its declaration as a number (io::default_value): a default the
// guide writes as one number ("3", "0.1", "true", "20 deg", "0 1/s") is that number in SI, so
// the guide and the reader cannot state two defaults. Exact: the same conversion makes both.
TEST(CaseSchema, ADefaultWrittenAsANumberIsTheNumberReadersTake) {
    const int checked = count_defaults(
        [](const io::KeyTable& table, const io::KeySpec& key, const std::string& text) {
            std::optional<double> number;
            if (text == "true" || text == "false") {
                number = text == "true" ? 1.0 : 0.0;
            } else if (std::string error; const auto q = io::parse_quantity(text, &error)) {
                number = q->value;
            }
            if (number) {
                EXPECT_DOUBLE_EQ(key.value, *number)
                    << table.name << "." << key.name << " = " << key.default_text;
            }
            return number.has_value();
        });
    // The schema's numeric defaults were found, not skipped: 89 of them when this was written.
    EXPECT_GE(checked, 80);
}

// A vector key's default written as components ("1 0 0", "0 m/s") is one io::default_vector
// reads, as its reader does; words ("the wall particles' centroid") are computed by the reader.
TEST(CaseSchema, AVectorDefaultWrittenAsComponentsIsOneReadersTake) {
    const int checked = count_defaults(
        [](const io::KeyTable& table, const io::KeySpec& key, const std::string& text) {
            std::string error;
            if (!key.type.ends_with("vector") || !io::parse_quantity_list(text, &error)) {
                return false;
            }
            EXPECT_NO_THROW(io::default_vector(std::span(&key, 1), key.name))
                << table.name << "." << key.name << " = " << key.default_text;
            return true;
        });
    EXPECT_GE(checked, 8); // the vector defaults were found, not skipped
}

// A key's path names its table without indices; root keys lie in no table.
TEST(CaseSchema, AKeysPathNamesItsTable) {
    EXPECT_EQ(io::table_of_key("sph.body[0].shape.cut[12].normal"), "sph.body.shape.cut");
    EXPECT_EQ(io::table_of_key("case.end_time"), "case");
    EXPECT_EQ(io::table_of_key("material[3].mu_i.i0"), "material.mu_i");
    EXPECT_EQ(io::table_of_key("title"), "");
}

/// Whether the schema declares `key` (a full path, "sph.body[0].spacing"). A model's keys may
/// stand in [[material]] itself or in its [material.MODEL] table: a key of "material" is
/// declared when [[material]] or any model's table declares it.
bool declared(const std::string& key) {
    const std::string table = io::table_of_key(key);
    const std::string name = key.substr(key.rfind('.') + 1);
    for (const io::KeyTable& part : case_schema()) {
        const bool same_table =
            part.name == table || (table == "material" && part.name.starts_with("material."));
        if (same_table && (part.user_keys || io::find_key_spec(part.keys, name) != nullptr)) {
            return true;
        }
    }
    return false;
}

/// Every case file of `folder` and below, but the material-point drivers (another format).
std::vector<std::string> case_files(const std::string& folder) {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
        if (entry.path().extension() == ".toml" &&
            entry.path().parent_path().filename() != "matpoint") {
            files.push_back(entry.path().string());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

// Every key a reader takes from a shipped case or a scene the tests load is declared in the
// schema, so that `help keys` and the user guide know every key a case can hold. The cases are
// loaded from a copy (the Gmsh cases mesh next to their case file), the wagon's deck made first
// by its own export script as the wagon's tests make it.
TEST(CaseSchema, EveryKeyTheShippedCasesReadIsDeclared) {
    const std::string copy = grainload::testing::test_folder("case_schema");
    std::filesystem::remove_all(copy);
    std::filesystem::create_directories(copy);
    for (const char* folder :
         {"cases", "tests/data/scene_warnings", "tests/data/watchdog", "tests/data/keyword"}) {
        std::filesystem::copy(grainload::testing::source_path(folder),
                              copy + "/" + std::filesystem::path(folder).filename().string(),
                              std::filesystem::copy_options::recursive);
    }
    const std::string wagon = copy + "/cases/hopper_wagon";
    const std::string export_deck = "python3 '" + wagon + "/export_k.py' --case '" + wagon +
                                    "/wagon_gravity.toml' > '" + wagon + "/export.log' 2>&1";
    ASSERT_EQ(std::system(export_deck.c_str()), 0);
    std::map<std::string, std::set<std::string>> undeclared; // key -> the cases that read it
    std::size_t loaded = 0;
    for (const std::string& file : case_files(copy)) {
        std::unique_ptr<Scene> scene;
        try {
            scene = Scene::load(file, {});
        } catch (const io::CaseError& error) {
            ADD_FAILURE() << file << " does not load: " << error.what();
            continue;
        }
        ++loaded;
        for (const std::string& key : scene->document->used_keys()) {
            if (!declared(key)) {
                undeclared[io::table_of_key(key) + "." + key.substr(key.rfind('.') + 1)].insert(
                    std::filesystem::path(file).filename().string());
            }
        }
    }
    EXPECT_GT(loaded, 60u);
    for (const auto& [key, files] : undeclared) {
        ADD_FAILURE() << key << " is read but not declared (" << *files.begin() << ", "
                      << files.size() << " case files)";
    }
    std::filesystem::remove_all(copy);
}

} // namespace
} // namespace grainload::app
