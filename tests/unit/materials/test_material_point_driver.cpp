#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "materials/material_case_reader.hpp"
#include "materials/material_point_reader.hpp"
#include "support/test_folder.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

namespace grainload::materials {
namespace {

constexpr const char* kElastic = R"(
[[material]]
name = "rubbery"
model = "linear_elastic"
density = "1000 kg/m^3"
youngs_modulus = "10 MPa"
poisson_ratio = 0.25
)";

struct DriverRun {
    std::unique_ptr<Material> material;
    std::vector<MaterialPointRecord> records;
};

DriverRun run_text(const std::string& text) {
    const auto document = io::CaseDocument::from_string(text, "driver.toml");
    const io::CaseTable root = document->root();
    DriverRun run{read_material(root.array_of_tables("material").front()), {}};
    drive_material_point(*run.material, read_material_point_path(root.table("path")), run.records);
    return run;
}

TEST(MaterialPointDriver, HydrostaticStrainPathGivesBulkResponse) {
    const DriverRun run = run_text(std::string(kElastic) + R"(
[path]
[[path.segment]]
steps = 4
strain_increment = { xx = -0.004, yy = -0.004, zz = -0.004 }
)");
    ASSERT_EQ(run.records.size(), 5u);
    const MaterialPointRecord& last = run.records.back();
    const double bulk = run.material->elastic().bulk_modulus;
    // Linear elasticity: I1 = 3 K eps_v exactly (round-off only, 1e-12 relative).
    EXPECT_NEAR(last.stress.head<3>().sum(), 3.0 * bulk * (-0.012), 1e-12 * bulk * 0.036);
    EXPECT_NEAR(last.strain(0), -0.004, 1e-15);
}

TEST(MaterialPointDriver, MixedControlGivesUniaxialStress) {
    const DriverRun run = run_text(std::string(kElastic) + R"(
[path]
[[path.segment]]
steps = 3
strain_increment = { xx = 0.003 }
stress = { yy = "0 Pa", zz = "0 Pa" }
)");
    const MaterialPointRecord& last = run.records.back();
    // Uniaxial stress: sigma_xx = E eps_xx, eps_yy = eps_zz = -nu eps_xx. Newton tolerance
    // 1e-10 relative on the stress bounds the error.
    EXPECT_NEAR(last.stress(0), 10e6 * 0.003, 1e-9 * 10e6 * 0.003);
    EXPECT_NEAR(last.stress(1), 0.0, 1e-9 * 10e6 * 0.003);
    EXPECT_NEAR(last.strain(1), -0.25 * 0.003, 1e-12);
    EXPECT_NEAR(last.strain(2), -0.25 * 0.003, 1e-12);
}

TEST(MaterialPointDriver, StressTargetsAreReachedLinearlyFromTheSegmentStart) {
    const DriverRun run = run_text(std::string(kElastic) + R"(
[path]
initial_stress = "-10 -10 -10 0 0 0 kPa"
[[path.segment]]
steps = 2
stress = { xx = "-30 kPa", yy = "-10 kPa", zz = "-10 kPa", xy = "5 kPa", yz = "0 kPa", zx = "0 kPa" }
)");
    EXPECT_NEAR(run.records[1].stress(0), -20e3, 1e-6);
    EXPECT_NEAR(run.records[2].stress(0), -30e3, 1e-6);
    EXPECT_NEAR(run.records[2].stress(3), 5e3, 1e-6);
}

TEST(MaterialPointDriver, RejectsAComponentControlledTwice) {
    EXPECT_THROW(run_text(std::string(kElastic) + R"(
[path]
[[path.segment]]
steps = 1
strain_increment = { xx = 0.001 }
stress = { xx = "1 kPa" }
)"),
                 io::CaseError);
}

std::string write_temp(const std::string& name, const std::string& text) {
    const std::string path = grainload::testing::process_folder() + name;
    std::ofstream(path) << text;
    return path;
}

std::vector<std::string> lines_of(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) {
        lines.push_back(line);
    }
    return lines;
}

TEST(MaterialPointDriver, RunWritesTheCsv) {
    const std::string driver = write_temp("vm_driver.toml", R"(
[[material]]
name = "steel"
model = "von_mises"
density = "7850 kg/m^3"
youngs_modulus = "200 GPa"
poisson_ratio = 0.3
yield_stress = "250 MPa"
tangent_modulus = "2 GPa"
[path]
[[path.segment]]
steps = 10
strain_increment = { xx = 0.01 }
stress = { yy = "0 Pa", zz = "0 Pa" }
)");
    const std::string csv = grainload::testing::process_folder() + "vm_driver.csv";
    std::vector<std::string> notices;
    ASSERT_EQ(run_material_point(driver, csv, notices), 0);
    const auto lines = lines_of(csv);
    ASSERT_EQ(lines.size(), 12u);
    EXPECT_EQ(lines[0], "step,strain_xx,strain_yy,strain_zz,strain_xy,strain_yz,strain_zx,"
                        "stress_xx,stress_yy,stress_zz,stress_xy,stress_yz,stress_zx,"
                        "equivalent_plastic_strain,plastic_volumetric_strain,cap_position,"
                        "region");
    EXPECT_TRUE(lines[1].ends_with(",0,,,elastic")) << lines[1];
    EXPECT_TRUE(lines.back().ends_with(",,failure_surface")) << lines.back();
}

TEST(MaterialPointDriver, UnreachableStressKeepsTheRowsAndReturnsOne) {
    // A perfectly plastic bar cannot carry 300 MPa: the rows before the limit are kept.
    const std::string driver = write_temp("vm_limit.toml", R"(
[[material]]
model = "von_mises"
density = "7850 kg/m^3"
youngs_modulus = "200 GPa"
poisson_ratio = 0.3
yield_stress = "250 MPa"
[path]
[[path.segment]]
steps = 6
stress = { xx = "300 MPa", yy = "0 Pa", zz = "0 Pa" }
)");
    const std::string csv = grainload::testing::process_folder() + "vm_limit.csv";
    std::vector<std::string> notices;
    EXPECT_EQ(run_material_point(driver, csv, notices), 1);
    // The path's failure is handed to the command line to print, naming the driver.
    ASSERT_EQ(notices.size(), 1u);
    EXPECT_EQ(notices.front().rfind(driver + ": ", 0), 0u) << notices.front();
    EXPECT_EQ(lines_of(csv).size(), 1u + 1u + 5u); // header, step 0, 200 ... 250 MPa
}

TEST(MaterialPointDriver, UnknownKeysAreRejected) {
    const std::string driver = write_temp("typo.toml", std::string(kElastic) + R"(
[path]
[[path.segment]]
steps = 1
strain_incremnt = { xx = 0.001 }
)");
    std::vector<std::string> notices;
    EXPECT_THROW(
        run_material_point(driver, grainload::testing::process_folder() + "typo.csv", notices),
        io::CaseError);
}

} // namespace
} // namespace grainload::materials
