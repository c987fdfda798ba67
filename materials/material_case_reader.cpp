#include "materials/material_case_reader.hpp"

#include "io/case_table.hpp"
#include "io/deck_ledger.hpp"
#include "io/named_index.hpp"
#include "materials/cone_fit.hpp"
#include "materials/drucker_prager.hpp"
#include "materials/generalized_cap.hpp"
#include "materials/linear_elastic.hpp"
#include "materials/lsdyna_material.hpp"
#include "materials/mohr_coulomb.hpp"
#include "materials/mu_i_material.hpp"
#include "materials/von_mises.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <string>

namespace grainload::materials {

namespace {

/// Density and the elastic pair as the table gives them, before stiffness_scale.
ElasticConstants read_moduli(const io::CaseTable& table) {
    namespace dim = io::dimension;
    const double density = table.positive_quantity("density", dim::kDensity);
    const bool by_young = table.has("youngs_modulus") || table.has("poisson_ratio");
    const bool by_moduli = table.has("bulk_modulus") || table.has("shear_modulus");
    if (by_young == by_moduli) {
        table.fail("", "expected either youngs_modulus and poisson_ratio, or bulk_modulus and "
                       "shear_modulus (exactly one pair)");
    }
    if (by_young) {
        const double young = table.positive_quantity("youngs_modulus", dim::kPressure);
        const double poisson = table.number("poisson_ratio");
        if (!(poisson > -1.0 && poisson < 0.5)) {
            table.fail("poisson_ratio", "expected a Poisson ratio in (-1, 0.5)");
        }
        return ElasticConstants::from_young(density, young, poisson);
    }
    return ElasticConstants::from_bulk_shear(
        density, table.positive_quantity("bulk_modulus", dim::kPressure),
        table.positive_quantity("shear_modulus", dim::kPressure));
}

DruckerPrager::Parameters parameters_from_angles(const io::CaseTable& table) {
    namespace dim = io::dimension;
    const double phi = table.quantity("friction_angle", dim::kAngle);
    const double cohesion = table.positive_quantity("cohesion", dim::kPressure, true);
    const double psi = table.quantity("dilatancy_angle", dim::kAngle);
    if (!(phi >= 0.0 && phi < std::acos(-1.0) / 2.0)) {
        table.fail("friction_angle", "expected an angle in [0, 90) deg");
    }
    if (!(psi >= 0.0 && psi <= phi)) {
        table.fail("dilatancy_angle", "expected an angle between 0 and the friction angle");
    }
    const ConeFit fit = cone_fit_from_name(
        table.choice("cone_fit", {"plane_strain", "compression", "extension", "inner"}));
    const ConeConstants cone = fit_cone(fit, phi, cohesion, psi);
    return {cone.alpha, cone.k, cone.alpha_flow};
}

DruckerPrager::Parameters parameters_from_thesis(const io::CaseTable& table) {
    namespace dim = io::dimension;
    if (table.has("friction_angle") || table.has("cohesion") || table.has("cone_fit")) {
        table.fail("dp_k", "give either (dp_k, dp_theta) or (friction_angle, cohesion, "
                           "dilatancy_angle, cone_fit), not both");
    }
    const double k = table.positive_quantity("dp_k", dim::kPressure, true);
    const double theta = table.number("dp_theta");
    if (!(theta >= 0.0)) {
        table.fail("dp_theta", "expected dp_theta >= 0");
    }
    const double theta_flow = table.number_or("dp_theta_flow", theta);
    if (!(theta_flow >= 0.0 && theta_flow <= theta)) {
        table.fail("dp_theta_flow", "expected a number between 0 and dp_theta");
    }
    return {theta, k, theta_flow};
}

/// A friction coefficient given as a number (`number_key`) or as the angle whose tangent it is
/// (`angle_key`), exactly one of the two.
double read_friction(const io::CaseTable& table, std::string_view number_key,
                     std::string_view angle_key) {
    const bool by_number = table.has(number_key);
    if (by_number == table.has(angle_key)) {
        table.fail(by_number ? angle_key : number_key,
                   "give either " + std::string(number_key) + " (a number) or " +
                       std::string(angle_key) + " (an angle, mu = tan), exactly one");
    }
    if (by_number) {
        return table.number(number_key);
    }
    const double angle = table.quantity(angle_key, io::dimension::kAngle);
    if (!(angle > 0.0 && angle < std::numbers::pi / 2.0)) {
        table.fail(angle_key, "expected an angle in (0, 90) deg");
    }
    return std::tan(angle);
}

/// The law's constants, checked in the order a user reads them.
MuILaw read_law(const io::CaseTable& table, double bulk_density) {
    namespace dim = io::dimension;
    MuILaw law;
    law.mu_s = read_friction(table, "mu_s", "angle_s");
    if (!(law.mu_s > 0.0)) {
        table.fail(table.has("mu_s") ? "mu_s" : "angle_s", "expected a static friction > 0");
    }
    law.mu_2 = read_friction(table, "mu_2", "angle_2");
    // sqrt(J2) = sqrt3 p is the compression meridian of phi = 90 deg: no steeper cone exists.
    if (!(law.mu_2 >= law.mu_s && law.mu_2 < std::sqrt(3.0))) {
        table.fail(table.has("mu_2") ? "mu_2" : "angle_2",
                   "expected a limit friction between the static one (" + std::to_string(law.mu_s) +
                       ") and sqrt(3)");
    }
    law.i0 = table.number("i0");
    if (!(law.i0 > 0.0) || !std::isfinite(law.i0)) {
        table.fail("i0", "expected I0 > 0");
    }
    law.grain_diameter = table.positive_quantity("grain_size", dim::kLength);
    law.grain_density = table.positive_quantity("grain_density", dim::kDensity);
    if (law.grain_density < bulk_density) {
        table.fail("grain_density", "expected the density of the grains' solid, at least the "
                                    "bulk density " +
                                        std::to_string(bulk_density) + " kg/m^3");
    }
    return law;
}

std::unique_ptr<Material> read_linear_elastic(const io::CaseTable& table) {
    return std::make_unique<LinearElastic>(read_elastic_constants(table));
}

std::unique_ptr<Material> read_von_mises(const io::CaseTable& table) {
    namespace dim = io::dimension;
    const ElasticConstants elastic = read_elastic_constants(table);
    const double yield = table.positive_quantity("yield_stress", dim::kPressure);
    const double tangent =
        table.positive_quantity_or("tangent_modulus", dim::kPressure,
                                   io::default_value(kVonMisesKeys, "tangent_modulus"), true);
    if (tangent >= elastic.young()) {
        table.fail("tangent_modulus", "expected a tangent modulus below Young's modulus");
    }
    const double beta =
        table.number_or("hardening_beta", io::default_value(kVonMisesKeys, "hardening_beta"));
    if (!(beta >= 0.0 && beta <= 1.0)) {
        table.fail("hardening_beta", "expected a number in [0, 1] (1 isotropic, 0 kinematic)");
    }
    return std::make_unique<VonMises>(elastic, yield, tangent, beta);
}

std::unique_ptr<Material> read_drucker_prager(const io::CaseTable& table) {
    const ElasticConstants elastic = read_elastic_constants(table);
    DruckerPrager::Parameters parameters = table.has("dp_k") || table.has("dp_theta")
                                               ? parameters_from_thesis(table)
                                               : parameters_from_angles(table);
    if (table.has("tension_cutoff")) {
        const double cutoff = table.quantity("tension_cutoff", io::dimension::kPressure);
        if (parameters.alpha > 0.0 && cutoff > parameters.k / parameters.alpha) {
            table.fail("tension_cutoff", "the cutoff on I1 lies beyond the cone apex k/alpha");
        }
        parameters.tension_cutoff = cutoff;
    }
    if (parameters.alpha == 0.0 && parameters.k == 0.0) {
        table.fail("", "a Drucker-Prager material with zero friction and zero cohesion has no "
                       "strength");
    }
    return std::make_unique<DruckerPrager>(elastic, parameters);
}

std::unique_ptr<Material> read_mohr_coulomb(const io::CaseTable& table) {
    namespace dim = io::dimension;
    const ElasticConstants elastic = read_elastic_constants(table);
    MohrCoulomb::Parameters p;
    p.friction_angle = table.quantity("friction_angle", dim::kAngle);
    if (!(p.friction_angle > 0.0 && p.friction_angle < std::numbers::pi / 2.0)) {
        table.fail("friction_angle", "expected an angle in (0, 90) deg");
    }
    p.cohesion = table.positive_quantity("cohesion", dim::kPressure, true);
    p.dilatancy_angle = table.quantity("dilatancy_angle", dim::kAngle);
    if (!(p.dilatancy_angle >= 0.0 && p.dilatancy_angle <= p.friction_angle)) {
        table.fail("dilatancy_angle", "expected an angle between 0 and the friction angle");
    }
    return std::make_unique<MohrCoulomb>(elastic, p);
}

std::unique_ptr<Material> read_mu_i(const io::CaseTable& table) {
    const ElasticConstants elastic = read_elastic_constants(table);
    double amplitude = 0.0;
    if (table.has("nonlocal_amplitude")) {
        amplitude = table.number("nonlocal_amplitude");
        if (!(amplitude > 0.0) || !std::isfinite(amplitude)) {
            table.fail("nonlocal_amplitude", "expected a non-local amplitude A > 0");
        }
    }
    return std::make_unique<MuIMaterial>(elastic, read_law(table, elastic.density), amplitude);
}

std::unique_ptr<Material> read_from_lsdyna(const io::CaseTable& table) {
    static constexpr const char* kGivenByDeck[] = {
        "density",   "youngs_modulus", "poisson_ratio", "bulk_modulus",   "shear_modulus", "cap_k",
        "cap_alpha", "cap_theta",      "cap_gamma",     "cap_beta",       "cap_D",         "cap_W",
        "cap_X0",    "cap_R",          "cap_toff",      "tension_cutoff", "cap_ftype",     "cap_c",
        "cap_n",     "cap_plot",       "cap_vec",       "cap_ivec",       "cap_semantics"};
    for (const char* key : kGivenByDeck) {
        if (table.has(key)) {
            table.fail(key, "the deck of 'from_lsdyna' gives this material's parameters "
                            "(MAT_025 semantics); remove the key or the deck");
        }
    }
    if (table.has("model") && table.string("model") != "generalized_cap") {
        table.fail("model", "a *MAT_GEOLOGIC_CAP_MODEL of 'from_lsdyna' is a generalized_cap; "
                            "give model = \"generalized_cap\" or leave the key out");
    }
    const io::CaseTable source = table.table("from_lsdyna");
    std::string error;
    const auto units = io::parse_keyword_units(source.string("units"), &error);
    if (!units) {
        source.fail("units", error);
    }
    const auto mid = source.name_list("mid");
    if (mid.size() != 1) {
        source.fail("mid", "expected one material id or label");
    }
    const std::string path = source.file_path("file");
    io::open_keyword_deck(source, path, *units);
    Mat025Material m;
    try {
        m = read_mat025(io::read_keyword_deck(path), mid.front(), *units);
    } catch (const std::invalid_argument& e) {
        source.fail("file", e.what());
    }
    source.deck_ledger().take(path, m.file, m.line);
    if (const std::string odd = implausible_values(m, *units); !odd.empty()) {
        std::ostringstream warning;
        warning << table.where("from_lsdyna") << ": material \"" << table.string("name")
                << "\" (MID " << mid.front() << " of "
                << std::filesystem::path(path).filename().string() << ") " << odd
                << ": expected the deck's own unit system in from_lsdyna.units";
        table.warn(warning.str());
    }
    const ElasticConstants elastic = m.elastic.scaled(read_stiffness_scale(table));
    return std::make_unique<GeneralizedCap>(elastic, m.parameters);
}

/// MAT_025 inputs grainload does not implement: giving one is an error, never silently ignored.
void refuse_unsupported(const io::CaseTable& table) {
    struct Unsupported {
        const char* key;
        const char* message;
    };
    static constexpr Unsupported kUnsupported[] = {
        {"cap_c", "MAT_025's C and N drive kinematic hardening of the failure envelope, which "
                  "grainload does not implement; remove the key (C = 0 in a deck means none)"},
        {"cap_n", "MAT_025's C and N drive kinematic hardening of the failure envelope, which "
                  "grainload does not implement; remove the key (C = 0 in a deck means none)"},
        {"cap_plot", "MAT_025's PLOT chooses the one history variable LS-DYNA writes; grainload "
                     "keeps all of them (cap_position, hardening_parameter, "
                     "plastic_volumetric_strain): remove the key"},
        {"cap_vec", "MAT_025's VEC chooses a fixed iteration count (0) or a fully iterative "
                    "return (1); grainload always iterates to convergence: remove the key"},
        {"cap_ivec", "MAT_025's VEC chooses a fixed iteration count (0) or a fully iterative "
                     "return (1); grainload always iterates to convergence: remove the key"},
    };
    for (const auto& [key, message] : kUnsupported) {
        if (table.has(key)) {
            table.fail(key, message);
        }
    }
    if (table.has("cap_ftype") && table.integer("cap_ftype") != 1) {
        table.fail("cap_ftype", "only FTYPE = 1 (soil/concrete: the cap contracts with "
                                "dilatancy) is implemented; FTYPE = 2 (rock: the cap never "
                                "contracts) is not");
    }
}

/// Exactly one of two names for one input (grainload's and MAT_025's).
std::string one_of(const io::CaseTable& table, const char* ours, const char* theirs) {
    if (table.has(ours) && table.has(theirs)) {
        table.fail(theirs, std::string("give either '") + ours + "' or '" + theirs +
                               "' (the same input), not both");
    }
    return table.has(theirs) ? theirs : ours;
}

/// T >= 0 from tension_cutoff, or from MAT_025's TOFF <= 0 (compression positive): T = -TOFF.
double tension_cutoff(const io::CaseTable& table) {
    const std::string key = one_of(table, "tension_cutoff", "cap_toff");
    if (key == "tension_cutoff") {
        return table.positive_quantity_or(key, io::dimension::kPressure,
                                          io::default_value(kGeneralizedCapKeys, "tension_cutoff"),
                                          true);
    }
    const double toff = table.quantity(key, io::dimension::kPressure);
    if (!(toff <= 0.0)) {
        table.fail(key, "expected TOFF <= 0: MAT_025 gives the tension cutoff as the lowest I1, "
                        "compression positive (tension_cutoff = -TOFF)");
    }
    return -toff;
}

std::unique_ptr<Material> read_generalized_cap(const io::CaseTable& table) {
    namespace dim = io::dimension;
    refuse_unsupported(table);
    cap::Parameters p;
    p.k = table.quantity(one_of(table, "cap_k", "cap_alpha"), dim::kPressure);
    p.theta = table.number("cap_theta");
    p.gamma = table.quantity("cap_gamma", dim::kPressure);
    p.beta = table.quantity("cap_beta", dim::kInversePressure);
    p.D = table.quantity("cap_D", dim::kInversePressure);
    p.W = table.number("cap_W");
    p.X0 = table.quantity("cap_X0", dim::kPressure);
    p.R = table.number("cap_R");
    p.tension = tension_cutoff(table);
    p.semantics =
        table.choice_or("cap_semantics", {"mat025", "lifted_x0"},
                        io::default_text(kGeneralizedCapKeys, "cap_semantics")) == "mat025"
            ? cap::Semantics::mat025
            : cap::Semantics::lifted_x0;
    const auto [key, message] = GeneralizedCap::check(p);
    if (!key.empty()) {
        table.fail(key, message);
    }
    return std::make_unique<GeneralizedCap>(read_elastic_constants(table), p);
}

constexpr std::array<std::string_view, 6> kModels{"linear_elastic",  "von_mises", "drucker_prager",
                                                  "generalized_cap", "mu_i",      "mohr_coulomb"};

std::unique_ptr<Material> read_model(const io::CaseTable& table, std::string_view model) {
    if (model == "linear_elastic") {
        return read_linear_elastic(table);
    }
    if (model == "von_mises") {
        return read_von_mises(table);
    }
    if (model == "drucker_prager") {
        return read_drucker_prager(table);
    }
    if (model == "mu_i") {
        return read_mu_i(table);
    }
    if (model == "mohr_coulomb") {
        return read_mohr_coulomb(table);
    }
    return read_generalized_cap(table);
}

} // namespace

double read_stiffness_scale(const io::CaseTable& table) {
    const double s =
        table.number_or("stiffness_scale", io::default_value(kMaterialKeys, "stiffness_scale"));
    if (!(s > 0.0) || !std::isfinite(s)) {
        table.fail("stiffness_scale", "expected a factor > 0 on the bulk and shear moduli");
    }
    return s;
}

ElasticConstants read_elastic_constants(const io::CaseTable& table) {
    return read_moduli(table).scaled(read_stiffness_scale(table));
}

std::unique_ptr<Material> read_material(const io::CaseTable& table) {
    if (table.has("from_lsdyna")) {
        return read_from_lsdyna(table);
    }
    const std::string model = table.choice(
        "model", {kModels[0], kModels[1], kModels[2], kModels[3], kModels[4], kModels[5]});
    // The other models' sub-tables are built too, and dropped: a mistake in the keys of a
    // model the case can be switched to is reported now, not when it is switched.
    for (const std::string_view other : kModels) {
        if (other != model && table.has(other)) {
            (void)read_model(table.with_sub_table(other), other);
        }
    }
    return read_model(table.with_sub_table(model), model);
}

MaterialLibrary read_material_library(const io::CaseTable& root) {
    MaterialLibrary library;
    std::vector<std::string> names;
    for (const auto& table : root.array_of_tables("material")) {
        std::string name = table.string("name");
        io::refuse_repeated_name(table, names, name, "material");
        std::unique_ptr<Material> material = read_material(table);
        // Read through the model's sub-table, where mu_i may hold its grain size too: one d for
        // the rheology and for Beverloo's k d.
        const io::CaseTable keys = table.with_sub_table(material->model());
        std::optional<double> grain_size =
            keys.has("grain_size")
                ? std::optional(keys.positive_quantity("grain_size", io::dimension::kLength))
                : std::nullopt;
        names.push_back(name);
        library.add(std::move(name), std::move(material), grain_size);
    }
    return library;
}

int read_material_index(const MaterialLibrary& library, const io::CaseTable& table,
                        std::string_view key) {
    const std::string name = table.string(key);
    const std::vector<std::string>& names = library.names();
    if (const auto found = std::find(names.begin(), names.end(), name); found != names.end()) {
        return static_cast<int>(found - names.begin());
    }
    const std::string known = io::quoted_names(names);
    table.fail(key, "no [[material]] is called \"" + name +
                        "\" (defined: " + (known.empty() ? std::string("none") : known) + ")");
}

} // namespace grainload::materials
