#include "fem/shell_model_reader.hpp"
#include "io/case_table.hpp"
#include "materials/material_case_reader.hpp"

#include <gtest/gtest.h>
#include <string>

namespace grainload::fem {
namespace {

struct Loaded {
    std::unique_ptr<io::CaseDocument> document;
    materials::MaterialLibrary materials;
    std::unique_ptr<ShellModel> model;
};

Loaded load(const std::string& text) {
    Loaded c;
    c.document = io::CaseDocument::from_string(text, "parts.toml");
    const io::SceneSettings scene = io::read_scene_settings(*c.document, "parts");
    c.materials = materials::read_material_library(c.document->root());
    c.model = read_shell_model(c.document->root(), scene, c.materials);
    c.document->reject_unknown_keys();
    return c;
}

const std::string kHeader = R"(
[case]
end_time = "1 s"
[[material]]
name = "steel"
model = "linear_elastic"
density = "7850 kg/m^3"
youngs_modulus = "210 GPa"
poisson_ratio = 0.3
[[material]]
name = "aluminium"
model = "linear_elastic"
density = "2700 kg/m^3"
youngs_modulus = "70 GPa"
poisson_ratio = 0.33
[fem]
)";

/// A simply supported plate part: `elements_x` wide, placed at `offset`, under a pressure.
std::string plate_part(const std::string& name, const std::string& material, double width,
                       int elements_x, double offset, const std::string& thickness,
                       const std::string& load) {
    return "[[fem.shell]]\nname = \"" + name + "\"\nmaterial = \"" + material +
           "\"\nthickness = \"" + thickness + "\"\ngenerator = \"plate\"\nlength_x = \"" +
           std::to_string(width) +
           " m\"\nlength_y = \"1 m\"\nelements_x = " + std::to_string(elements_x) +
           "\nelements_y = 8\noffset = \"" + std::to_string(offset) + " 0 0 m\"\n" + load +
           "[[fem.shell.boundary]]\nnode_set = \"y0\"\ndofs = \"uz\"\n"
           "[[fem.shell.boundary]]\nnode_set = \"y1\"\ndofs = \"uz\"\n";
}

const std::string kPressure = "[[fem.shell.load]]\ntype = \"pressure\"\nvalue = \"-1 kPa\"\n";
const std::string kEdgeX0 = "[[fem.shell.boundary]]\nnode_set = \"x0\"\ndofs = \"uz\"\n"
                            "[[fem.shell.boundary]]\npoint = \"0 0 0 m\"\ndofs = \"ux uy rz\"\n"
                            "[[fem.shell.boundary]]\npoint = \"0 1 0 m\"\ndofs = \"ux\"\n";
const std::string kEdgeX1 = "[[fem.shell.boundary]]\nnode_set = \"x1\"\ndofs = \"uz\"\n";

double centre_deflection(const ShellModel& model) {
    const ShellAnalysis& a = model.analysis();
    return a.displacement(a.mesh().nearest_node(Vec3(0.5, 0.5, 0.0))).z();
}

// Two [[fem.shell]] halves of a simply supported square plate, joined where their nodes
// coincide, are the one-part plate: the same mesh, so the same centre deflection to round-off.
// The reference, Navier's series for a simply supported square plate under uniform pressure
// (Timoshenko & Woinowsky-Krieger, table 8: w = 0.00406 q a^4 / D), is met by the 8 x 8 MITC4
// mesh within its discretisation error (1 %: measured -0.3 %).
TEST(ShellParts, TwoHalvesOfAPlateAreThePlate) {
    Loaded whole = load(kHeader + plate_part("plate", "steel", 1.0, 8, 0.0, "10 mm",
                                             kPressure + kEdgeX0 + kEdgeX1));
    Loaded halves =
        load(kHeader + plate_part("left", "steel", 0.5, 4, 0.0, "10 mm", kPressure + kEdgeX0) +
             plate_part("right", "steel", 0.5, 4, 0.5, "10 mm", kPressure + kEdgeX1));
    ASSERT_EQ(halves.model->analysis().mesh().node_count(),
              whole.model->analysis().mesh().node_count());
    EXPECT_EQ(halves.model->part_names(), (std::vector<std::string>{"left", "right"}));
    whole.model->advance(0.0, 1.0);
    halves.model->advance(0.0, 1.0);
    const double w = centre_deflection(*whole.model);
    const double d = 210e9 * 1e-6 / (12.0 * (1.0 - 0.09));
    const double navier = -0.00406 * 1000.0 / d;
    EXPECT_NEAR(w, navier, 0.01 * std::abs(navier));
    EXPECT_NEAR(centre_deflection(*halves.model), w, 1e-9 * std::abs(w));
    // A part's own sets are "<part>.<set>"; the first part's also keep their plain names.
    EXPECT_TRUE(halves.model->analysis().mesh().has_node_set("right.x1"));
    EXPECT_TRUE(halves.model->analysis().mesh().has_node_set("x0"));
}

// Each part carries its own material and thickness: the self-weight of a steel half (10 mm)
// and an aluminium half (4 mm) is carried by the supports, whose reactions add up to the
// weight sum rho_k t_k A_k g (to the solver's tolerance) -- the part's density enters its
// gravity load, not the first part's. [case] gravity is left out: its default, -9.81 m/s^2
// along z in 3D, is the one every module uses.
TEST(ShellParts, EachPartHasItsOwnMaterialAndThickness) {
    const std::string gravity = "[[fem.shell.load]]\ntype = \"gravity\"\n";
    Loaded halves =
        load(kHeader + plate_part("steel", "steel", 0.5, 4, 0.0, "10 mm", gravity + kEdgeX0) +
             plate_part("alu", "aluminium", 0.5, 4, 0.5, "4 mm", gravity + kEdgeX1));
    halves.model->advance(0.0, 1.0);
    const Eigen::VectorXd reactions = halves.model->analysis().reactions();
    double vertical = 0.0;
    for (Eigen::Index n = 0; n < reactions.size(); n += 6) {
        vertical += reactions(n + 2);
    }
    const double weight = 9.81 * 0.5 * (7850.0 * 0.010 + 2700.0 * 0.004);
    EXPECT_NEAR(vertical, weight, 1e-6 * weight); // the supports push up
    for (const ShellElement& e : halves.model->analysis().mesh().elements()) {
        EXPECT_DOUBLE_EQ(e.thickness, e.part == 0 ? 0.010 : 0.004);
    }
}

TEST(ShellParts, PartsNeedDistinctNames) {
    const std::string part = plate_part("plate", "steel", 1.0, 2, 0.0, "10 mm", "");
    try {
        load(kHeader + part + part);
        FAIL() << "no CaseError";
    } catch (const io::CaseError& e) {
        EXPECT_NE(std::string(e.what()).find("already defined"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace grainload::fem
