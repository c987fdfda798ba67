#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "io/key_places.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace {

using namespace grainload::io;

constexpr const char* kCase = R"([sph]
[[sph.sink]]
name = "drain"
type = "plane"
point = "0 -1 0 m"
normal = "0 -1 0"
)";

// The places a reader keeps are the table's own: a check made after the table is gone fails and
// warns with the same file, line, column and key as CaseTable::fail and CaseTable::where, also
// for a key the table does not hold (placed at the table).
TEST(KeyPlaces, NameTheSameFileLineAndKeyAsTheTable) {
    const auto document = CaseDocument::from_string(kCase, "places.toml");
    const CaseTable sink = document->root().table("sph").array_of_tables("sink").front();
    const KeyPlaces places(sink, {"normal", "min"});
    EXPECT_TRUE(places.has("normal"));
    EXPECT_FALSE(places.has("min"));
    EXPECT_EQ(places.where("normal"), sink.where("normal"));
    EXPECT_EQ(places.where("normal"), "places.toml:6:10: key 'sph.sink[0].normal'");
    EXPECT_EQ(places.where("min"), sink.where("min"));
    std::string from_table;
    std::string from_places;
    try {
        sink.fail("normal", "points into the scene");
    } catch (const CaseError& e) {
        from_table = e.what();
    }
    try {
        places.fail("normal", "points into the scene");
    } catch (const CaseError& e) {
        from_places = e.what();
    }
    EXPECT_EQ(from_places, from_table);
    EXPECT_EQ(from_places, "places.toml:6:10: key 'sph.sink[0].normal': points into the scene");
    // A key the reader did not keep is a programming error, not the user's.
    EXPECT_THROW((void)places.where("point"), std::logic_error);
}

} // namespace
