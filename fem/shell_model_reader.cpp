#include "fem/shell_model_reader.hpp"

#include "fem/shell_case_reader.hpp"
#include "io/case_table.hpp"

#include <map>
#include <stdexcept>
#include <string>

namespace grainload::fem {

namespace dim = io::dimension;

namespace {

/// The declared default of a [fem] key, at compile time.
constexpr double declared(std::string_view key) {
    for (const io::KeySpec& spec : kFemKeys) {
        if (spec.name == key) {
            return spec.value;
        }
    }
    throw std::logic_error("undeclared [fem] key");
}

// The settings' own defaults (for analyses built without a case) are the declared ones.
constexpr NewtonSettings kNewtonDefaults{};
static_assert(kNewtonDefaults.displacement_tolerance == declared("displacement_tolerance"));
static_assert(kNewtonDefaults.force_tolerance == declared("force_tolerance"));
static_assert(kNewtonDefaults.energy_tolerance == declared("energy_tolerance"));
static_assert(kNewtonDefaults.max_iterations == declared("max_iterations"));
static_assert(kNewtonDefaults.max_cutbacks == declared("max_cutbacks"));
static_assert(ShellModelSettings{}.increments_per_step == declared("increments_per_step"));
static_assert(ShellModelSettings{}.integrator_gamma == declared("newmark_gamma"));

/// The declared default of a [fem] key.
double fallback(std::string_view key) {
    return io::default_value(kFemKeys, key);
}

std::int64_t integer_fallback(std::string_view key) {
    return static_cast<std::int64_t>(fallback(key));
}

NewtonSettings read_newton(const io::CaseTable& fem) {
    NewtonSettings s;
    s.displacement_tolerance =
        fem.number_or("displacement_tolerance", fallback("displacement_tolerance"));
    s.force_tolerance = fem.number_or("force_tolerance", fallback("force_tolerance"));
    s.energy_tolerance = fem.number_or("energy_tolerance", fallback("energy_tolerance"));
    s.max_iterations =
        static_cast<int>(fem.integer_or("max_iterations", integer_fallback("max_iterations")));
    s.max_cutbacks =
        static_cast<int>(fem.integer_or("max_cutbacks", integer_fallback("max_cutbacks")));
    return s;
}

/// A dynamic analysis' integrator: Newmark's gamma, or HHT's alpha with gamma = 1/2 - alpha
/// (Hilber, Hughes & Taylor 1977: second order).
void read_integrator(const io::CaseTable& fem, ShellModelSettings& settings) {
    if (fem.choice_or("integrator", {"newmark", "hht"}, io::default_text(kFemKeys, "integrator")) ==
        "hht") {
        const double alpha = fem.number_or("hht_alpha", fallback("hht_alpha"));
        if (alpha < -1.0 / 3.0 || alpha > 0.0) {
            fem.fail("hht_alpha", "expected -1/3 <= alpha <= 0");
        }
        settings.integrator_alpha = alpha;
        settings.integrator_gamma = 0.5 - alpha;
    } else {
        settings.integrator_gamma = fem.number_or("newmark_gamma", fallback("newmark_gamma"));
        if (settings.integrator_gamma < 0.5) {
            fem.fail("newmark_gamma", "expected gamma >= 0.5 (unconditional stability)");
        }
    }
    settings.mass = fem.choice_or("mass", {"lumped", "consistent"},
                                  io::default_text(kFemKeys, "mass")) == "consistent"
                        ? MassMatrix::consistent
                        : MassMatrix::lumped;
}

} // namespace

ShellModelSettings read_shell_model_settings(const io::CaseTable& fem, double end_time) {
    ShellModelSettings settings;
    settings.dynamic = fem.choice_or("analysis", {"static", "dynamic"},
                                     io::default_text(kFemKeys, "analysis")) == "dynamic";
    if (settings.dynamic) {
        settings.time_step = fem.positive_quantity("time_step", dim::kTime);
    }
    settings.newton = read_newton(fem);
    settings.load_time = fem.positive_quantity_or("load_time", dim::kTime, end_time);
    settings.increments_per_step = static_cast<int>(
        fem.integer_or("increments_per_step", integer_fallback("increments_per_step")));
    if (settings.dynamic) {
        read_integrator(fem, settings);
    }
    return settings;
}

std::unique_ptr<ShellModel> read_shell_model(const io::CaseTable& root,
                                             const io::SceneSettings& scene,
                                             const materials::MaterialLibrary& materials) {
    const io::CaseTable fem = root.table("fem");
    const std::string kinematics = fem.choice_or("kinematics", {"linear", "total_lagrangian"},
                                                 io::default_text(kFemKeys, "kinematics"));
    const ShellModelSettings settings = read_shell_model_settings(fem, scene.end_time);
    const std::vector<io::CaseTable> shells = fem.array_of_tables("shell");
    if (shells.empty()) {
        fem.fail("shell", "expected at least one [[fem.shell]] table");
    }
    auto [mesh, parts] = read_shell_parts(fem, shells, materials);
    std::vector<std::string> part_names;
    for (const ShellPart& part : parts) {
        part_names.push_back(part.name);
    }
    auto analysis = std::make_unique<ShellAnalysis>(
        std::move(mesh), std::move(parts),
        kinematics == "linear" ? Kinematics::linear : Kinematics::total_lagrangian);
    // Every [[fem.time_function]] becomes a history of its own.
    std::map<std::string, int> histories;
    for (auto& [name, function] : read_time_functions(fem)) {
        histories[name] = analysis->add_history(function);
    }
    std::vector<ShellMonitor> monitors;
    std::vector<ShellReaction> reactions;
    for (std::size_t k = 0; k < shells.size(); ++k) {
        const PartScope scope{static_cast<int>(k), part_names[k]};
        read_shell_boundaries(shells[k], histories, scope, *analysis);
        read_shell_loads(shells[k], scene.gravity, histories, scope, *analysis);
        for (ShellMonitor& monitor : read_shell_monitors(shells[k], analysis->mesh())) {
            monitors.push_back(std::move(monitor));
        }
        for (ShellReaction& reaction : read_shell_reactions(shells[k], analysis->mesh(), scope)) {
            reactions.push_back(std::move(reaction));
        }
    }
    return std::make_unique<ShellModel>(settings, std::move(analysis), std::move(part_names),
                                        std::move(monitors), std::move(reactions));
}

} // namespace grainload::fem
