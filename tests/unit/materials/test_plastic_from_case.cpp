#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "materials/drucker_prager.hpp"
#include "materials/generalized_cap.hpp"
#include "materials/material_case_reader.hpp"
#include "materials/von_mises.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <string>
#include <vector>

namespace grainload::materials {
namespace {

std::unique_ptr<Material> build(const std::string& body) {
    const auto document = io::CaseDocument::from_string("[[material]]\n" + body, "case.toml");
    auto material = read_material(document->root().array_of_tables("material").front());
    document->reject_unknown_keys();
    return material;
}

constexpr const char* kSandElastic =
    "density = \"1700 kg/m^3\"\nbulk_modulus = \"30 MPa\"\nshear_modulus = \"10 MPa\"\n";

TEST(PlasticFromCase, VonMisesReadsUnitsAndHardening) {
    const auto m = build("model = \"von_mises\"\ndensity = \"2700 kg/m^3\"\n"
                         "youngs_modulus = \"1.65e5 MPa\"\npoisson_ratio = 0.33\n"
                         "yield_stress = \"290 MPa\"\ntangent_modulus = \"1 GPa\"\n"
                         "hardening_beta = 0.25\n");
    const auto& vm = dynamic_cast<const VonMises&>(*m);
    EXPECT_DOUBLE_EQ(vm.yield_stress(), 290e6);
    EXPECT_DOUBLE_EQ(vm.beta(), 0.25);
    // Thesis 4.6.2.1: E_p = E E_T / (E - E_T).
    EXPECT_NEAR(vm.plastic_modulus(), 1.65e11 * 1e9 / (1.65e11 - 1e9), 1e-3);
    EXPECT_EQ(m->state_size(), 7);
}

TEST(PlasticFromCase, VonMisesRefusesTangentAboveYoung) {
    EXPECT_THROW(build("model = \"von_mises\"\ndensity = \"2700 kg/m^3\"\n"
                       "youngs_modulus = \"1 GPa\"\npoisson_ratio = 0.3\n"
                       "yield_stress = \"1 MPa\"\ntangent_modulus = \"2 GPa\"\n"),
                 io::CaseError);
}

TEST(PlasticFromCase, DruckerPragerFromAnglesWithCutoff) {
    const auto m = build(std::string("model = \"drucker_prager\"\n") + kSandElastic +
                         "friction_angle = \"30 deg\"\ncohesion = \"10 kPa\"\n"
                         "dilatancy_angle = \"0 deg\"\ncone_fit = \"plane_strain\"\n"
                         "tension_cutoff = \"5 kPa\"\n");
    const auto& p = dynamic_cast<const DruckerPrager&>(*m).parameters();
    // Plane strain, psi = 0: alpha = sin(phi) / 3, k = c cos(phi).
    EXPECT_NEAR(p.alpha, 0.5 / 3.0, 1e-14);
    EXPECT_NEAR(p.k, 10e3 * std::cos(std::numbers::pi / 6.0), 1e-9);
    EXPECT_EQ(p.alpha_flow, 0.0);
    EXPECT_DOUBLE_EQ(p.tension_cutoff, 5e3);
}

TEST(PlasticFromCase, DruckerPragerFromThesisConstantsDefaultsToTheApex) {
    const auto m = build(std::string("model = \"drucker_prager\"\n") + kSandElastic +
                         "dp_k = \"0.03858 MPa\"\ndp_theta = 0.03\n");
    const auto& p = dynamic_cast<const DruckerPrager&>(*m).parameters();
    EXPECT_DOUBLE_EQ(p.k, 0.03858e6);
    EXPECT_DOUBLE_EQ(p.alpha, 0.03);
    EXPECT_DOUBLE_EQ(p.alpha_flow, 0.03);
    EXPECT_NEAR(p.tension_cutoff, 0.03858e6 / 0.03, 1e-6);
}

TEST(PlasticFromCase, DruckerPragerRefusesMixedFormsAndCutoffBeyondApex) {
    const std::string base = std::string("model = \"drucker_prager\"\n") + kSandElastic;
    EXPECT_THROW(build(base + "dp_k = \"1 kPa\"\ndp_theta = 0.1\nfriction_angle = \"30 deg\"\n"),
                 io::CaseError);
    EXPECT_THROW(build(base + "dp_k = \"1 kPa\"\ndp_theta = 0.1\ntension_cutoff = \"20 kPa\"\n"),
                 io::CaseError);
    EXPECT_THROW(build(base + "friction_angle = \"30 deg\"\ncohesion = \"1 kPa\"\n"
                              "dilatancy_angle = \"40 deg\"\ncone_fit = \"inner\"\n"),
                 io::CaseError);
    EXPECT_THROW(build(base + "friction_angle = \"30 deg\"\ncohesion = \"1 kPa\"\n"
                              "dilatancy_angle = \"0 deg\"\ncone_fit = \"outer\"\n"),
                 io::CaseError);
}

// One material, two models' keys in [material.MODEL] sub-tables: `model` picks one, and
// --set switches it. The other sub-table is checked too, a key given
// both in a sub-table and above it is an error, and nothing is left unread.
constexpr const char* kSwitchable = R"([[material]]
model = "generalized_cap"
density = "2099 kg/m^3"
bulk_modulus = "30.62 MPa"
shear_modulus = "8.23 MPa"
[material.drucker_prager]
dp_k = "0.03858 MPa"
dp_theta = 0.03
[material.generalized_cap]
cap_k = "0.03858 MPa"
cap_theta = 0.03
cap_gamma = "0.03858 MPa"
cap_beta = "9.0 1/MPa"
cap_D = "7.25 1/MPa"
cap_W = 0.18
cap_X0 = "0 MPa"
cap_R = 2.0
)";

std::unique_ptr<Material> build_document(const std::string& text,
                                         const std::vector<std::string>& sets = {}) {
    const auto document = io::CaseDocument::from_string(text, "case.toml");
    for (const std::string& assignment : sets) {
        document->set(assignment);
    }
    auto material = read_material(document->root().array_of_tables("material").front());
    document->reject_unknown_keys();
    return material;
}

TEST(PlasticFromCase, ModelSubTablesLetSetSwitchTheModel) {
    const auto cap = build_document(kSwitchable);
    EXPECT_EQ(cap->model(), "generalized_cap");
    EXPECT_DOUBLE_EQ(cap->density(), 2099.0);
    const auto dp = build_document(kSwitchable, {"material[0].model=\"drucker_prager\""});
    ASSERT_EQ(dp->model(), "drucker_prager");
    const auto& p = dynamic_cast<const DruckerPrager&>(*dp).parameters();
    EXPECT_DOUBLE_EQ(p.k, 0.03858e6); // the sub-table's key
    EXPECT_DOUBLE_EQ(p.alpha, 0.03);
    EXPECT_DOUBLE_EQ(dp->density(), 2099.0); // the shared key above it
    // A mistake in the model not chosen is still reported.
    std::string typo = kSwitchable;
    typo.replace(typo.find("dp_theta"), 8, "dp_thetta");
    EXPECT_THROW(build_document(typo), io::CaseError);
    // A key both in a sub-table and above it.
    std::string twice = kSwitchable;
    twice.replace(twice.find("[material.drucker_prager]"), 25,
                  "[material.drucker_prager]\ndensity = \"2000 kg/m^3\"");
    EXPECT_THROW(build_document(twice), io::CaseError);
}

TEST(PlasticFromCase, StiffnessScaleScalesTheModuliAndNothingElse) {
    // stiffness_scale s: K and G times s, density and plastic parameters unchanged; the wave
    // speed falls by sqrt(s) and unscaled_p_wave_speed() gives back the real material's.
    const std::string cap =
        "model = \"generalized_cap\"\ndensity = \"2099 kg/m^3\"\n"
        "bulk_modulus = \"30.62 GPa\"\nshear_modulus = \"8.23 GPa\"\n"
        "cap_k = \"0.03858 MPa\"\ncap_theta = 0.03\ncap_gamma = \"0.03858 MPa\"\n"
        "cap_beta = \"9.0 1/MPa\"\ncap_D = \"7.25 1/MPa\"\ncap_W = 0.18\n"
        "cap_X0 = \"0 MPa\"\ncap_R = 2.0\n";
    const auto full = build(cap);
    const auto soft = build(cap + "stiffness_scale = 0.001\n");
    EXPECT_EQ(soft->elastic().bulk_modulus, 0.001 * full->elastic().bulk_modulus);
    EXPECT_EQ(soft->elastic().shear_modulus, 0.001 * full->elastic().shear_modulus);
    EXPECT_EQ(soft->density(), full->density());
    EXPECT_EQ(full->elastic().stiffness_scale, 1.0);
    // sqrt(0.001) in the wave speed; round-off of the square roots only.
    constexpr double kRoundOff = 1e-14;
    const double c = full->elastic().p_wave_speed();
    EXPECT_NEAR(soft->elastic().p_wave_speed(), std::sqrt(0.001) * c, kRoundOff * c);
    EXPECT_NEAR(soft->elastic().unscaled_p_wave_speed(), c, kRoundOff * c);
    EXPECT_EQ(full->elastic().unscaled_p_wave_speed(), c);
    const auto& a = dynamic_cast<const GeneralizedCap&>(*full).parameters();
    const auto& b = dynamic_cast<const GeneralizedCap&>(*soft).parameters();
    EXPECT_EQ(a.k, b.k);
    EXPECT_EQ(a.X0, b.X0);
    EXPECT_EQ(a.D, b.D);
    // The same key scales any model's elastic part; zero and negative factors are refused.
    const auto elastic = build("model = \"linear_elastic\"\n" + std::string(kSandElastic) +
                               "stiffness_scale = 0.1\n");
    EXPECT_DOUBLE_EQ(elastic->elastic().bulk_modulus, 3e6);
    EXPECT_THROW(build(cap + "stiffness_scale = 0\n"), io::CaseError);
    EXPECT_THROW(build(cap + "stiffness_scale = -1\n"), io::CaseError);
    EXPECT_THROW(build(cap + "stiffness_scale = \"0.1 MPa\"\n"), io::CaseError);
}

} // namespace
} // namespace grainload::materials
