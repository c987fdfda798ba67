#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "sph/body_shape_reader.hpp"
#include "support/test_folder.hpp"

#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

namespace fs = std::filesystem;

// Sand of 1600 kg/m^3 on a 10 mm lattice: a particle holds 1600 * (0.01 m)^3 = 1.6e-3 kg,
// written in mm-t-s as 1.6e-6 t. Part 7 ("sand"): a 2 x 2 x 2 block of cell centres, NID 1..8
// by NEND generation on one card; part 8: one particle 0.5 % heavier, part 9 one 25 % heavier.
constexpr const char* kDeck = R"(*KEYWORD
*NODE
1, 5, 5, 5
2, 15, 5, 5
3, 5, 15, 5
4, 15, 15, 5
5, 5, 5, 15
6, 15, 5, 15
7, 5, 15, 15
8, 15, 15, 15
9, 100, 0, 0
10, 200, 0, 0
*PART
sand
7
*ELEMENT_SPH
1, 7, 1.6e-6, 8
9, 8, 1.608e-6
10, 9, 2.0e-6
*END
)";

constexpr double kDensity = 1600.0;
constexpr double kSpacing = 0.01;

std::vector<Vec3> particles(const std::string& shape_keys, int dimension = 3) {
    // One folder per test: ctest runs the tests of this file as parallel processes, and a
    // deck rewritten by one while another reads it reads as a deck without particles.
    const std::string dir = grainload::testing::process_folder() + "keyword_body_" +
                            ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(dir);
    std::ofstream(dir + "/sand.k") << kDeck;
    auto document = io::CaseDocument::from_string(
        "[shape]\ntype = \"lsdyna\"\nfile = \"sand.k\"\nunits = \"mm-t-s\"\n" + shape_keys,
        dir + "/case.toml");
    document->spatial_dimension = dimension;
    return generate_body_points(document->root().table("shape"), kSpacing, dimension, kDensity);
}

std::string case_error_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const io::CaseError& error) {
        return error.what();
    }
    return "no CaseError";
}

TEST(KeywordBody, ParticlesOfOnePartInMetres) {
    const auto points = particles("parts = \"sand\"\n");
    ASSERT_EQ(points.size(), 8u);
    // mm -> m: one rounding of a coordinate below 0.02 m.
    EXPECT_NEAR((points[0] - Vec3(0.005, 0.005, 0.005)).norm(), 0.0, 1e-17);
    EXPECT_NEAR((points[7] - Vec3(0.015, 0.015, 0.015)).norm(), 0.0, 1e-17);
    // Part 8's mass is 0.5 % off 1.6e-3 kg, within the default 1 %.
    EXPECT_EQ(particles("parts = [7, 8]\n").size(), 9u);
}

TEST(KeywordBody, RefusesMassesOffDensityTimesVolume) {
    const std::string heavy = case_error_of([] { particles("parts = [7, 9]\n"); });
    EXPECT_NE(heavy.find("shape.file"), std::string::npos) << heavy;
    EXPECT_NE(heavy.find("sand.k:19: *ELEMENT_SPH particle 10 has the mass 0.002"),
              std::string::npos)
        << heavy;
    EXPECT_NE(heavy.find("1 of 9 particles differ by more than mass_tolerance = 0.01"),
              std::string::npos)
        << heavy;
    // A stated tolerance of 30 % accepts it; 0.4 % refuses part 8's 0.5 %.
    EXPECT_EQ(particles("parts = [7, 9]\nmass_tolerance = 0.3\n").size(), 9u);
    EXPECT_NE(
        case_error_of([] { particles("parts = 8\nmass_tolerance = 0.004\n"); }).find("particle 9"),
        std::string::npos);
    EXPECT_NE(case_error_of([] { particles("parts = \"gravel\"\n"); }).find("no *PART titled"),
              std::string::npos);
    EXPECT_NE(case_error_of([] { particles("parts = \"sand\"\n", 2); }).find("off z = 0"),
              std::string::npos);
}

} // namespace
} // namespace grainload::sph
