#include "io/case_table.hpp"

#include <gtest/gtest.h>

namespace {

using namespace grainload;
using namespace grainload::io;
namespace dim = grainload::io::dimension;

constexpr const char* kCase = R"(
[case]
end_time = "1.5 s"
gravity = "0 0 -9.81 m/s^2"

[[material]]
name = "sand"
density = "2099 kg/m^3"
friction_angle = ["30 deg"]

[[material]]
name = "steel"
density = "7.85 t/m^3"
)";

std::string error_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const CaseError& error) {
        return error.what();
    }
    return "";
}

TEST(CaseTable, ReadsQuantitiesVectorsAndArraysOfTables) {
    auto document = CaseDocument::from_string(kCase, "scene.toml");
    const CaseTable root = document->root();
    const CaseTable settings = root.table("case");
    EXPECT_DOUBLE_EQ(settings.quantity("end_time", dim::kTime), 1.5);
    EXPECT_EQ(settings.vector("gravity", dim::kAcceleration), Vec3(0, 0, -9.81));
    const auto materials = root.array_of_tables("material");
    ASSERT_EQ(materials.size(), 2u);
    EXPECT_EQ(materials[1].path(), "material[1]");
    EXPECT_DOUBLE_EQ(materials[1].quantity("density", dim::kDensity), 7850.0);
    EXPECT_NEAR(materials[0].quantity_list("friction_angle", dim::kAngle)[0], M_PI / 6, 1e-15);
}

TEST(CaseTable, WrongDimensionNamesFileLineKeyAndExpectation) {
    auto document = CaseDocument::from_string(kCase, "scene.toml");
    const std::string message = error_of([&] {
        document->root().array_of_tables("material")[0].quantity("density", dim::kPressure);
    });
    EXPECT_NE(message.find("scene.toml:8:"), std::string::npos) << message;
    EXPECT_NE(message.find("material[0].density"), std::string::npos) << message;
    EXPECT_NE(message.find("expected a pressure"), std::string::npos) << message;
    EXPECT_NE(message.find("a density"), std::string::npos) << message;
}

TEST(CaseTable, UnreadKeysAreReportedAsUnknown) {
    auto document = CaseDocument::from_string(kCase, "scene.toml");
    const CaseTable root = document->root();
    root.table("case").quantity("end_time", dim::kTime);
    const std::string message = error_of([&] { document->reject_unknown_keys(); });
    EXPECT_NE(message.find("scene.toml:4:"), std::string::npos) << message;
    EXPECT_NE(message.find("unknown key 'case.gravity'"), std::string::npos) << message;
}

TEST(CaseTable, MissingKeyPointsAtItsTable) {
    auto document = CaseDocument::from_string(kCase, "scene.toml");
    const std::string message =
        error_of([&] { document->root().array_of_tables("material")[1].string("model"); });
    EXPECT_NE(message.find("scene.toml:11:"), std::string::npos) << message;
    EXPECT_NE(message.find("material[1].model': missing required key"), std::string::npos)
        << message;
}

TEST(CaseTable, OverridesReplaceAndAddKeysWithUnits) {
    auto document = CaseDocument::from_string(kCase, "scene.toml");
    document->set("case.end_time=0.25 s");
    document->set("material[1].density=\"8 t/m^3\"");
    document->set("sph.time_step=2 ms");
    document->set("case.dimension=2");
    const CaseTable root = document->root();
    EXPECT_DOUBLE_EQ(root.table("case").quantity("end_time", dim::kTime), 0.25);
    EXPECT_EQ(root.table("case").integer("dimension"), 2);
    EXPECT_DOUBLE_EQ(root.array_of_tables("material")[1].quantity("density", dim::kDensity),
                     8000.0);
    EXPECT_DOUBLE_EQ(root.table("sph").quantity("time_step", dim::kTime), 0.002);
    const std::string message =
        error_of([&] { document->root().table("sph").quantity("time_step", dim::kLength); });
    EXPECT_NE(message.find("--set sph.time_step=2 ms"), std::string::npos) << message;
    EXPECT_FALSE(error_of([&] { document->set("material[7].density=1"); }).empty());
    EXPECT_FALSE(error_of([&] { document->set("no_equals_sign"); }).empty());
}

TEST(CaseTable, SyntaxErrorsCarryLineAndColumn) {
    const std::string message =
        error_of([] { CaseDocument::from_string("[case]\nend_time = \"1 s\n", "bad.toml"); });
    EXPECT_NE(message.find("bad.toml:2:"), std::string::npos) << message;
    EXPECT_NE(message.find("TOML syntax error"), std::string::npos) << message;
}

TEST(CaseTable, ChoicesListTheAllowedValues) {
    auto document = CaseDocument::from_string("kernel = \"cubic\"\n", "k.toml");
    const std::string message = error_of([&] {
        document->root().choice("kernel", {"cubic_spline", "wendland_c2"});
    });
    EXPECT_NE(message.find("\"cubic_spline\", \"wendland_c2\""), std::string::npos) << message;
}

} // namespace
