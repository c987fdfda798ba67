#include "coupling/coupling_case_reader.hpp"

#include "coupling/added_mass.hpp"
#include "coupling/window_limits.hpp"
#include "fem/shell_model_reader.hpp"
#include "io/case_table.hpp"
#include "io/named_index.hpp"
#include "sph/sph_case_reader.hpp"
#include "sph/sph_model_reader.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace grainload::coupling {

namespace dim = io::dimension;

namespace {

/// The declared default of a [coupling] key, at compile time.
constexpr double declared(std::string_view key) {
    for (const io::KeySpec& spec : kCouplingKeys) {
        if (spec.name == key) {
            return spec.value;
        }
    }
    throw std::logic_error("undeclared [coupling] key");
}

// A default-constructed CouplingSettings holds the declared defaults: one default per key.
constexpr CouplingSettings kDefaults{};
static_assert(kDefaults.max_subcycles == declared("max_subcycles"));
static_assert(kDefaults.max_iterations == declared("max_iterations"));
static_assert(kDefaults.relaxation == declared("relaxation"));
static_assert(kDefaults.iteration_tolerance == declared("iteration_tolerance"));
static_assert(kDefaults.energy_error_limit == declared("energy_error_limit"));
static_assert(kDefaults.added_mass == declared("added_mass"));

/// Refuses an interface whose wall particles (ShellWall::particle_bound) would need more than
/// the `spare` particles left in memory, before any is laid, at its `spacing` (or `part` when
/// the bodies' spacing is taken), with the count and a spacing that fits; takes them from
/// `spare` otherwise. The count goes as spacing^-2, so the fitting spacing is the spacing
/// times the square root of the excess.
void refuse_oversized_interface(const io::CaseTable& table, const fem::ShellMesh& mesh,
                                const std::vector<Index>& elements, const ShellWallLayout& layout,
                                std::optional<double>& spare) {
    if (!spare) {
        return;
    }
    const double count = ShellWall::particle_bound(mesh, elements, layout);
    if (!(count > *spare)) {
        *spare -= count;
        return;
    }
    std::ostringstream message;
    message.precision(3);
    message << "the interface would lay about " << count << " wall particles on its "
            << elements.size() << " elements (" << layout.layers << " layers at " << layout.spacing
            << " m), more than the about " << std::max(*spare, 0.0)
            << " that fit in the memory left beside the bodies, walls and shells (MemAvailable "
               "in /proc/meminfo): expected a spacing of at least about "
            << layout.spacing * std::sqrt(count / std::max(*spare, 1.0))
            << " m (the bodies' spacing bounds it: coarsen both), or a smaller part";
    table.fail(table.has("spacing") ? "spacing" : "part", message.str());
}

void read_friction(const io::CaseTable& coupling, const sph::SphModel& sph,
                   std::vector<sph::SphModel::WallDefinition>& walls) {
    for (const io::CaseTable& table : coupling.array_of_tables("friction")) {
        const std::string body = table.string("body");
        if (sph.body_id(body) < 0) {
            table.fail("body", "expected the name of an [[sph.body]]");
        }
        const std::string name = table.string("part");
        sph::SphModel::WallDefinition* wall = nullptr;
        for (auto& w : walls) {
            wall = w.name == name ? &w : wall;
        }
        if (wall == nullptr) {
            table.fail("part", "expected the name of a [[coupling.interface]] (" +
                                   io::quoted_names(walls, &sph::SphModel::WallDefinition::name) +
                                   ")");
        }
        if (!wall->bodies.empty() && std::find(wall->bodies.begin(), wall->bodies.end(),
                                               sph.body_id(body)) == wall->bodies.end()) {
            table.fail("body", "interface \"" + name + "\" does not act on body \"" + body +
                                   "\" (its `bodies`): expected one of them");
        }
        const sph::CoulombCoefficients mu = sph::read_coulomb_coefficients(table);
        const sph::SphModel::WallDefinition::Friction friction{body, mu.mu_static, mu.mu_kinetic};
        for (const auto& other : wall->friction) {
            if (other.body == body) {
                table.fail("part", "this body-part pair already has friction coefficients");
            }
        }
        wall->friction.push_back(friction);
    }
}

/// How to lay the wall particles of an interface (`side`, `spacing`, `layers`): as a
/// [[sph.wall]] (sph::read_wall_layout), but one layer on the mid-surface of a part with sand
/// on both sides.
ShellWallLayout read_layout(const io::CaseTable& table, const sph::SphModel& sph, double support) {
    ShellWallLayout layout;
    const std::string side = table.choice("side", {"positive", "negative", "both"});
    layout.side = side == "positive"   ? ContactSide::positive
                  : side == "negative" ? ContactSide::negative
                                       : ContactSide::both;
    const sph::WallLayout wall = sph::read_wall_layout(table, sph.spacing(), support);
    layout.spacing = wall.spacing;
    layout.layers = wall.layers;
    if (layout.side == ContactSide::both) {
        // Sand on both faces: the one layer on the mid-surface, whatever the support.
        if (table.has("layers") && wall.layers != 1) {
            table.fail("layers", "a part with sand on both sides has one layer of wall "
                                 "particles, on its mid-surface: expected layers = 1 or none");
        }
        layout.layers = 1;
    }
    return layout;
}

/// The interfaces of [coupling] as the SPH side's walls, and the coupled parts that drive them.
struct Interfaces {
    std::vector<CoupledPart> parts; ///< the parts that send the sand's load to the shell
    std::vector<std::string> rigid; ///< the names of the rigid ones
    std::vector<sph::SphModel::WallDefinition> walls;
};

/// The coupled part of one [[coupling.interface]] (its part, name and elements; `coupled`
/// marks the elements already taken), refused when its name is taken.
CoupledPart read_part(const io::CaseTable& table, const fem::ShellModel& fem,
                      const Interfaces& read, std::vector<char>& coupled) {
    const auto& names = fem.part_names();
    CoupledPart part;
    const int index = part_index(table, "part", names);
    part.name = table.string_or("name", names[static_cast<std::size_t>(index)]);
    for (const sph::SphModel::WallDefinition& other : read.walls) {
        if (other.name == part.name) {
            table.fail(table.has("name") ? "name" : "part",
                       "an interface called \"" + part.name +
                           "\" already exists: expected one interface per part, or a `name` "
                           "for each");
        }
    }
    part.elements = interface_elements(table, fem.analysis().mesh(), index, coupled);
    return part;
}

/// One [[coupling.interface]]: its part, the wall particles laid on it (within the `spare`
/// particles), and the SPH wall they make, added to `read`.
void read_interface(const io::CaseTable& table, const sph::SphModel& sph, fem::ShellModel& fem,
                    double support, std::optional<double>& spare, std::vector<char>& coupled,
                    Interfaces& read) {
    CoupledPart part = read_part(table, fem, read, coupled);
    const ShellWallLayout layout = read_layout(table, sph, support);
    refuse_oversized_interface(table, fem.analysis().mesh(), part.elements, layout, spare);
    part.side = layout.side;
    part.wall = std::make_shared<ShellWall>(fem.analysis(), part.elements, layout);
    sph::SphModel::WallDefinition wall;
    wall.name = part.name;
    wall.points = part.wall->points();
    wall.normals = part.wall->normals();
    wall.samples = part.wall->samples();
    wall.two_sided = layout.side == ContactSide::both;
    wall.bodies = sph::read_wall_bodies(table, sph.body_names());
    wall.spacing = layout.spacing;
    // A rigid part keeps its wall where the shell was built (no driver) and sends no load
    // back: the same scene with a rigid wall, one key away.
    const bool rigid = table.boolean_or("rigid", io::default_value(kInterfaceKeys, "rigid") != 0.0);
    wall.driver = rigid ? nullptr : part.wall;
    read.walls.push_back(std::move(wall));
    if (rigid) {
        read.rigid.push_back(part.name);
    } else {
        read.parts.push_back(std::move(part));
    }
}

/// Every [[coupling.interface]] (at least one), in the file's order.
Interfaces read_interfaces(const io::CaseTable& coupling, const sph::SphModel& sph,
                           fem::ShellModel& fem, std::optional<double> spare) {
    const double support = sph.support_radius();
    Interfaces read;
    const auto interfaces = coupling.array_of_tables("interface");
    std::vector<char> coupled(static_cast<std::size_t>(fem.analysis().mesh().element_count()), 0);
    if (interfaces.empty()) {
        coupling.fail("interface", "expected at least one [[coupling.interface]] table");
    }
    for (const io::CaseTable& table : interfaces) {
        read_interface(table, sph, fem, support, spare, coupled, read);
    }
    return read;
}

/// Adds the interfaces' walls to the SPH model, builds it, and gives each coupled part the
/// index of its wall in the solver's list.
void build_walls(const io::CaseTable& root, sph::SphModel& sph, Interfaces& read) {
    for (auto& wall : read.walls) {
        sph.add_wall(std::move(wall));
    }
    sph::build_sph_scene(sph, root);
    const auto& sph_walls = sph.solver()->walls();
    for (CoupledPart& part : read.parts) {
        for (std::size_t k = 0; k < sph_walls.size(); ++k) {
            if (sph_walls[k].name == part.name) {
                part.wall_index = static_cast<int>(k);
            }
        }
    }
}

/// The staggered window's limits (window_limits.hpp): refused when no SPH step fits in it, or
/// when it is beyond twice its limit (unless `beyond_window_limit`), warned about when beyond
/// the limit itself.
WindowLimits check_window(const io::CaseTable& coupling, const CouplingSettings& settings,
                          const sph::SphModel& sph, fem::ShellModel& fem,
                          const std::vector<CoupledPart>& parts, double end_time) {
    const double sph_step = sph.stable_time_step();
    if (settings.window < sph_step * (1.0 - 1e-9)) {
        std::ostringstream message;
        message << "the coupling window " << settings.window << " s is shorter than the SPH step "
                << sph_step << " s: expected a window of at least one SPH step";
        coupling.fail("window", message.str());
    }
    const WindowLimits limits =
        estimate_window_limits(sph, fem, parts, settings.relaxation, end_time, settings.added_mass);
    const bool beyond = coupling.boolean_or(
        "beyond_window_limit", io::default_value(kCouplingKeys, "beyond_window_limit") != 0.0);
    if (settings.max_iterations <= 1 && !beyond) {
        if (auto refusal =
                window_refusal(limits, settings.window, fem.dynamic(), settings.relaxation)) {
            coupling.fail("window", *refusal);
        }
    }
    if (settings.max_iterations <= 1) {
        if (auto warning =
                window_warning(limits, settings.window, fem.dynamic(), settings.relaxation)) {
            coupling.warn(*warning);
        }
    }
    return limits;
}

/// Warns about an added mass that makes the wall follow the load late.
void warn_about_lag(const io::CaseTable& coupling, const CouplingSettings& settings,
                    const WindowLimits& limits, double end_time) {
    if (auto warning =
            added_mass_lag_warning(limits, settings.window, settings.added_mass, end_time)) {
        coupling.warn(*warning);
    }
}

} // namespace

void warn_about_ramp(const io::CaseTable& coupling, const fem::ShellModel& fem,
                     const CouplingSettings& settings, double end_time) {
    // Time is physical in a coupled run: the ramp that orders a stand-alone static analysis's
    // load steps would put the structure's own weight on over the run (the wagon's body carried
    // 23 % of it when its load was heaviest with such a ramp; docs/validation/hopper_wagon.md).
    // A ramp over a few windows (the tipping cone's plate: two) is a start-up, not that.
    if (fem.has_ramped_loads() &&
        fem.load_time() > std::max(settings.window, 0.1 * end_time) * (1.0 + 1e-9)) {
        std::ostringstream warning;
        warning << "the shell's own loads without a time function (gravity, pressures, nodal "
                   "forces) grow linearly until [fem] load_time = "
                << fem.load_time()
                << " s (by default end_time); in a coupled run time is physical and a structure "
                   "carries its weight before the sand arrives: set load_time to one window ("
                << settings.window << " s) unless the ramp is meant";
        coupling.warn(warning.str());
    }
}

CouplingSettings read_settings(const io::CaseTable& table, const fem::ShellModel& fem) {
    CouplingSettings settings;
    if (table.has("window") || !fem.dynamic()) {
        settings.window = table.positive_quantity("window", dim::kTime);
    } else {
        settings.window = fem.stable_time_step();
    }
    const auto fallback = [](std::string_view key) {
        return io::default_value(kCouplingKeys, key);
    };
    const auto subcycles =
        table.integer_or("max_subcycles", static_cast<std::int64_t>(fallback("max_subcycles")));
    if (subcycles < 0) {
        table.fail("max_subcycles", "expected 0 (no limit) or a positive number of SPH steps");
    }
    settings.max_subcycles = static_cast<int>(subcycles);
    const auto iterations =
        table.integer_or("max_iterations", static_cast<std::int64_t>(fallback("max_iterations")));
    if (iterations < 1 || iterations > 1000) {
        table.fail("max_iterations", "expected 1 (staggered) to 1000 passes per window");
    }
    settings.max_iterations = static_cast<int>(iterations);
    settings.relaxation = table.number_or("relaxation", fallback("relaxation"));
    settings.accelerator =
        table.choice_or("accelerator", {"aitken", "quasi_newton"},
                        io::default_text(kCouplingKeys, "accelerator")) == "quasi_newton"
            ? Accelerator::quasi_newton
            : Accelerator::aitken;
    if (!(settings.relaxation > 0.0 && settings.relaxation <= 1.0)) {
        table.fail("relaxation", "expected a relaxation factor in (0, 1]");
    }
    settings.iteration_tolerance =
        table.number_or("iteration_tolerance", fallback("iteration_tolerance"));
    if (!(settings.iteration_tolerance >= 0.0)) {
        table.fail("iteration_tolerance", "expected a tolerance >= 0");
    }
    settings.energy_error_limit =
        table.number_or("energy_error_limit", fallback("energy_error_limit"));
    if (!(settings.energy_error_limit > 0.0)) {
        table.fail("energy_error_limit", "expected a positive fraction of the interface work");
    }
    settings.added_mass = table.number_or("added_mass", fallback("added_mass"));
    if (!(settings.added_mass >= 0.0 && settings.added_mass <= 100.0)) {
        table.fail("added_mass", "expected an added-mass factor from 0 (none) to 100");
    }
    if (settings.added_mass > 0.0 && fem.dynamic()) {
        table.fail("added_mass", "expected 0 with a dynamic shell: its own inertia answers the "
                                 "sand's in the window it moves (the added mass is for a static "
                                 "shell)");
    }
    return settings;
}

int part_index(const io::CaseTable& table, const std::string& key,
               const std::vector<std::string>& parts) {
    const std::string name = table.string(key);
    for (std::size_t k = 0; k < parts.size(); ++k) {
        if (parts[k] == name) {
            return static_cast<int>(k);
        }
    }
    table.fail(key, "expected the name of a [[fem.shell]] part (" + io::quoted_names(parts) + ")");
}

std::vector<Index> interface_elements(const io::CaseTable& table, const fem::ShellMesh& mesh,
                                      int part, std::vector<char>& coupled) {
    std::vector<Index> elements = mesh.part_elements(part);
    if (table.has("element_sets")) {
        std::vector<char> chosen(coupled.size(), 0);
        for (const std::string& set : table.name_list("element_sets")) {
            if (!mesh.has_element_set(set)) {
                std::string known;
                for (const auto& entry : mesh.element_sets()) {
                    known += (known.empty() ? "\"" : ", \"") + entry.first + "\"";
                }
                table.fail("element_sets",
                           "no element set \"" + set + "\" in the mesh (" + known + ")");
            }
            for (const Index e : mesh.element_set(set)) {
                chosen[static_cast<std::size_t>(e)] = 1;
            }
        }
        std::erase_if(elements, [&](Index e) { return !chosen[static_cast<std::size_t>(e)]; });
        if (elements.empty()) {
            table.fail("element_sets", "the sets hold no element of the part");
        }
    }
    for (const Index e : elements) {
        if (coupled[static_cast<std::size_t>(e)]) {
            table.fail(table.has("element_sets") ? "element_sets" : "part",
                       "element " + std::to_string(e) +
                           " already belongs to an interface: expected each element in one");
        }
        coupled[static_cast<std::size_t>(e)] = 1;
    }
    return elements;
}

std::unique_ptr<CoupledModel> read_coupled_model(const io::CaseTable& root,
                                                 const io::SceneSettings& scene,
                                                 const materials::MaterialLibrary& materials,
                                                 std::optional<double> spare_particles) {
    const io::CaseTable coupling = root.table("coupling");
    if (!root.has("sph") || !root.has("fem")) {
        coupling.fail("", "a coupling joins SPH bodies and shells: expected [sph] with "
                          "[[sph.body]] and [fem] with [[fem.shell]] tables");
    }
    auto sph = sph::read_sph_bodies(root, scene, materials);
    auto fem = fem::read_shell_model(root, scene, materials);
    const CouplingSettings settings = read_settings(coupling, *fem);
    Interfaces read = read_interfaces(coupling, *sph, *fem, spare_particles);
    read_friction(coupling, *sph, read.walls);
    build_walls(root, *sph, read);
    const WindowLimits limits =
        check_window(coupling, settings, *sph, *fem, read.parts, scene.end_time);
    warn_about_ramp(coupling, *fem, settings, scene.end_time);
    warn_about_lag(coupling, settings, limits, scene.end_time);
    if (settings.added_mass > 0.0) {
        fem->analysis().set_node_springs(added_mass_springs(fem->analysis().mesh(), read.parts,
                                                            limits.sand_mass, settings.window,
                                                            settings.added_mass));
    }
    auto model = std::make_unique<CoupledModel>(std::move(sph), std::move(fem),
                                                std::move(read.parts), settings);
    model->set_window_limits(limits);
    model->set_rigid_interfaces(std::move(read.rigid));
    return model;
}

} // namespace grainload::coupling
