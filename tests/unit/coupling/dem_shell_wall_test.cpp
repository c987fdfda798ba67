// A DEM grain on a coupled shell: where it meets the plate, and what the shell's nodes receive.

#include "coupling/coupling_case_reader.hpp"
#include "coupling/dem_coupled_model.hpp"
#include "io/case_table.hpp"
#include "io/scene_settings.hpp"
#include "materials/material_case_reader.hpp"
#include "materials/material_library.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <numbers>
#include <string>

namespace grainload::coupling {
namespace {

constexpr double kG = 9.81;
constexpr double kRadius = 0.005;   // the grain's
constexpr double kThickness = 0.01; // the plate's

/// One glass sphere above a 0.1 m steel plate of 2 x 2 elements (clamped at x = 0), coupled
/// with relaxation 1 (the shell's load is the last window's mean), under gravity tilted by 20
/// degrees about y; `centre` its position, `coupling` and `interface` more keys of those
/// tables. One scene at a time: the library is shared.
std::unique_ptr<DemCoupledModel> sphere_on_plate(const std::string& centre,
                                                 const std::string& coupling = "",
                                                 const std::string& interface = "") {
    const double theta = 20.0 * std::numbers::pi / 180.0;
    const std::string text =
        "[case]\nend_time = \"1 s\"\ngravity = \"" + std::to_string(kG * std::sin(theta)) + " 0 " +
        std::to_string(-kG * std::cos(theta)) +
        " m/s^2\"\n"
        "[[material]]\nname = \"glass\"\nmodel = \"linear_elastic\"\ndensity = \"2500 "
        "kg/m^3\"\nyoungs_modulus = \"10 MPa\"\npoisson_ratio = 0.3\n"
        "[[material]]\nname = \"steel\"\nmodel = \"linear_elastic\"\ndensity = \"7850 "
        "kg/m^3\"\nyoungs_modulus = \"210 GPa\"\npoisson_ratio = 0.3\n"
        "[dem.contact]\nlaw = \"hertz_mindlin\"\ngamma_n = \"300 1/s\"\ngamma_t = \"300 "
        "1/s\"\nfriction = 0.5\n"
        "[[dem.body]]\nname = \"bead\"\nmaterial = \"glass\"\nradius = \"5 mm\"\nrotation = "
        "false\ncentre = \"" +
        centre +
        "\"\n"
        "[fem]\nanalysis = \"static\"\n"
        "[[fem.shell]]\nname = \"plate\"\nmaterial = \"steel\"\nthickness = \"10 mm\"\n"
        "generator = \"plate\"\nlength_x = \"100 mm\"\nlength_y = \"100 mm\"\nelements_x = "
        "2\nelements_y = 2\n"
        "[[fem.shell.boundary]]\nnode_set = \"x0\"\ndofs = \"all\"\n"
        "[coupling]\nwindow = \"2 ms\"\nrelaxation = 1.0\n" +
        coupling + "\n[[coupling.interface]]\npart = \"plate\"\nside = \"positive\"\n" + interface;
    auto document = io::CaseDocument::from_string(text, "grain_on_plate.toml");
    const io::SceneSettings settings = io::read_scene_settings(*document, "grain_on_plate");
    const io::CaseTable root = document->root();
    // The shell's parts keep their materials by reference, as the scene keeps its library.
    static materials::MaterialLibrary library;
    library = materials::read_material_library(root);
    auto model = read_dem_coupled_model(root, settings, library);
    document->reject_unknown_keys();
    return model;
}

/// Runs `model` for `seconds` in its windows.
void run(DemCoupledModel& model, double seconds) {
    const double window = model.stable_time_step();
    const auto windows = static_cast<int>(std::lround(seconds / window));
    for (int k = 0; k < windows; ++k) {
        model.advance(k * window, window);
    }
}

// The grains meet the plate of its thickness about the mid-surface: a sphere set down at
// rest with its centre r + t/2 above it (z = 10 mm) starts in touch and stays there, its
// centre sinking by the Hertz overlap of its weight only (below 1 % of r).
TEST(DemShellWall, GrainsMeetThePlateAtHalfItsThicknessFromTheMidSurface) {
    auto model = sphere_on_plate("30 60 10 mm");
    run(*model, 0.2);
    const double z = model->dem().grains().position[0].z();
    EXPECT_LT(z, kRadius + 0.5 * kThickness);
    EXPECT_GT(z, kRadius + 0.5 * kThickness - 0.01 * kRadius);
}

// A grain held on the plate by friction under tilted gravity: the plate carries its weight,
// the load's force m g at the contact point p = y + (t/2) n on the plate's face. The nodes'
// loads (f_a = lambda_a F, m_a = lambda_a (t/2) n x F) add up to the force, and their moments
// about the origin, sum x_a x f_a + m_a, to p x F: the same statics (bound: the grain's
// residual motion after 0.3 s, 1e-6 of the weight and of its moment). Without the moments
// m_a the sum would miss (t/2) n x F, 5e-3 m x 0.34 m g.
TEST(DemShellWall, NodalLoadsAreStaticallyEquivalentToTheContactForce) {
    auto model = sphere_on_plate("30 60 10 mm");
    run(*model, 0.3);
    const double mass = 2500.0 * 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
    const double theta = 20.0 * std::numbers::pi / 180.0;
    const Vec3 weight = mass * kG * Vec3(std::sin(theta), 0.0, -std::cos(theta));
    const Vec3 centre = model->dem().grains().position[0];
    // The contact point on the plate's face (z = t/2) below the grain's centre.
    const Vec3 point(centre.x(), centre.y(), 0.5 * kThickness);
    const Eigen::VectorXd& load = model->interface_load();
    const fem::ShellAnalysis& analysis = model->fem().analysis();
    Vec3 force = Vec3::Zero();
    Vec3 moment = Vec3::Zero();
    for (Index n = 0; n < analysis.mesh().node_count(); ++n) {
        const Vec3 f = load.segment<3>(6 * n);
        force += f;
        moment += (analysis.mesh().node(n) + analysis.displacement(n)).cross(f) +
                  Vec3(load.segment<3>(6 * n + 3));
    }
    const double scale = weight.norm();
    EXPECT_NEAR((force - weight).norm(), 0.0, 1e-6 * scale);
    EXPECT_NEAR((moment - point.cross(weight)).norm(), 0.0, 1e-6 * scale * point.norm());
}

// A rigid interface (`rigid = true`) is a mesh wall where the shell was built: the grain rests
// on it, the DEM's wall carries its weight (bound 1e-6, as above) and the shell none of it.
TEST(DemShellWall, ARigidInterfaceCarriesTheGrainAndLeavesTheShellUnloaded) {
    auto model = sphere_on_plate("30 60 10 mm", "", "rigid = true\n");
    run(*model, 0.3);
    const double mass = 2500.0 * 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
    const double theta = 20.0 * std::numbers::pi / 180.0;
    const Vec3 weight = mass * kG * Vec3(std::sin(theta), 0.0, -std::cos(theta));
    ASSERT_EQ(model->dem().walls().size(), 1u);
    EXPECT_FALSE(model->dem().walls()[0].follows());
    EXPECT_NEAR((model->dem().walls()[0].force - weight).norm(), 0.0, 1e-6 * weight.norm());
    EXPECT_FALSE(model->loads_shell());
    EXPECT_EQ(model->interface_load().norm(), 0.0);
    EXPECT_EQ(model->fem().analysis().dofs().norm(), 0.0);
}

// Iterated windows (max_iterations > 1): each window is run again from its start under the load
// it produced until that load stops changing, so the shell's load is the window's own, not the
// last one's. The grain comes to rest on the plate as in the staggered run: the load carries
// its weight (bound 1e-6, as above), and the last window's passes ended within the iteration
// tolerance (1e-3; a grain at rest repeats its load in the first pass).
TEST(DemShellWall, IteratedWindowsEndWithTheLoadTheyProduce) {
    auto model = sphere_on_plate("30 60 10 mm", "max_iterations = 10");
    run(*model, 0.3);
    const double mass = 2500.0 * 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
    const double theta = 20.0 * std::numbers::pi / 180.0;
    const Vec3 weight = mass * kG * Vec3(std::sin(theta), 0.0, -std::cos(theta));
    EXPECT_NEAR((load_resultant(model->interface_load()) - weight).norm(), 0.0,
                1e-6 * weight.norm());
    int iterated = 0;
    for (const WindowRecord& window : model->monitor().windows()) {
        EXPECT_TRUE(window.load_change <= 1e-3 || window.iterations == 10) << window.time;
        iterated += window.iterations > 1 ? 1 : 0;
    }
    EXPECT_GT(iterated, 0); // the grain's landing took more than one pass
}

} // namespace
} // namespace grainload::coupling
