#pragma once
// The reader of a coupled scene: [sph], [fem] and [coupling] joined in one CoupledModel.

#include "coupling/coupled_model.hpp"
#include "coupling/dem_coupled_model.hpp"
#include "io/key_spec.hpp"
#include "io/scene_settings.hpp"
#include "materials/material_library.hpp"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::coupling {

/// The [coupling] table's own keys (docs/user-guide/coupling.md).
inline constexpr std::array<io::KeySpec, 9> kCouplingKeys{{
    {"window", "time", "the dynamic shell's `fem.time_step`; required for a static shell",
     "FEM step Δt_F: the shell is solved once per window, SPH sub-cycles through it"},
    {"max_subcycles", "integer", "0 (no limit)",
     "a window needing more SPH steps is cut to max_subcycles SPH steps", 0.0},
    {"max_iterations", "integer", "1",
     "1: staggered with a one-window lag; > 1: fixed-point iteration per window", 1.0},
    {"relaxation", "number in (0, 1]", "0.5",
     "ω of the load update F ← F + ω (F_sand − F): every window (staggered), or the iteration's "
     "first step (then Aitken)",
     0.5},
    {"accelerator", "`aitken` or `quasi_newton`", "aitken",
     "the iterated window's load update after its first step: Aitken's relaxation, or the "
     "interface quasi-Newton IQN-ILS (for walls soft enough that Aitken does not converge)"},
    {"iteration_tolerance", "number", "1e-3",
     "the iteration stops when ‖F_new − F‖ / ‖F_new‖ is below it", 1e-3},
    {"energy_error_limit", "number", "0.05",
     "exit 3 when the energy the interface creates (the shell receives more than the sand's "
     "work) exceeds this fraction of the interface work and has grown for 10 windows; "
     "dissipation is no error",
     0.05},
    {"added_mass", "number >= 0", "0",
     "static shell: springs of β m_s / Δt_F² (the sand's areal mass behind the wall over the "
     "window squared) from each coupled node to its position at the window's start, so that "
     "the shell feels the sand's inertia in the window it moves; 0: none. With β (2/ω − 1) ≥ 1 "
     "the staggered window has no lower limit; a static equilibrium is unchanged",
     0.0},
    {"beyond_window_limit", "boolean", "false",
     "true: run a staggered window longer than twice its estimated stable limit (refused "
     "otherwise); the energy watchdog is then the only guard",
     0.0},
}};

/// The keys of each [[coupling.interface]] table.
inline constexpr std::array<io::KeySpec, 8> kInterfaceKeys{{
    {"part", "string", "", "a [[fem.shell]] part name"},
    {"name", "string", "the part name",
     "the interface's wall name (needed when a part has several interfaces)"},
    {"element_sets", "list of strings", "the whole part",
     "only these element sets of the part (Gmsh physical surfaces, *SET_SHELL_LIST); each "
     "element in one interface at most"},
    {"side", "`positive`, `negative` or `both`", "",
     "the side of the part's element normals (right-hand rule of the node order) the sand is "
     "on; both: either side, one layer of wall particles on the mid-surface"},
    {"spacing", "length", "the bodies' spacing", "wall particle spacing on the shell"},
    {"layers", "integer", "enough to fill the kernel support: ⌈2h / spacing⌉ (3h quintic)",
     "layers of wall particles behind the contact face"},
    {"rigid", "boolean", "false",
     "true: the part's surface is a rigid wall where the shell was built; the sand's load on it "
     "is reported (`wall_PART_force_*`) but not applied to the shell",
     0.0},
    {"bodies", "list of strings", "all bodies",
     "the [[sph.body]] names the part acts on; the others pass through it as if it were not "
     "there (no contact, friction, damping or load)"},
}};

/// The keys of each [[coupling.friction]] table: Coulomb friction between a body and an
/// interface's wall.
inline constexpr std::array<io::KeySpec, 4> kFrictionKeys{{
    {"body", "string", "", "an [[sph.body]] name"},
    {"part", "string", "",
     "an interface's name (its part's name unless the interface has its own `name`)"},
    {"mu_static", "number >= 0", "", "μ_s, the static friction coefficient"},
    {"mu_kinetic", "number", "`mu_static`", "μ_k, the sliding friction coefficient, 0 ≤ μ_k ≤ μ_s"},
}};

/// The [coupling] table's settings for the shell `fem` (its window required for a static
/// shell, the dynamic shell's step by default).
CouplingSettings read_settings(const io::CaseTable& table, const fem::ShellModel& fem);
/// The index among `parts` of the [[fem.shell]] part named by `key`.
int part_index(const io::CaseTable& table, const std::string& key,
               const std::vector<std::string>& parts);
/// The elements of one interface: its part's, or those of its `element_sets`; none may
/// belong to an interface before it (`coupled` flags them).
std::vector<Index> interface_elements(const io::CaseTable& table, const fem::ShellMesh& mesh,
                                      int part, std::vector<char>& coupled);
/// Warns about a ramp of the shell's own loads over more than a few windows: in a coupled run
/// time is physical.
void warn_about_ramp(const io::CaseTable& coupling, const fem::ShellModel& fem,
                     const CouplingSettings& settings, double end_time);

/// A scene with [sph], [fem] and [coupling]: the bodies, the shell parts, one wall per
/// [[coupling.interface]] on the shell (named after its part or its `name`), friction from
/// [[coupling.friction]] (body, interface name as `part`, mu_static, mu_kinetic), joined in one
/// CoupledModel. `spare_particles`: the SPH particles that fit in memory beside the bodies,
/// walls and shells (app/resources/memory_guard.hpp); the interfaces' wall particles, counted on
/// the shell mesh before any is laid, may not exceed them (std::nullopt: no limit).
std::unique_ptr<CoupledModel> read_coupled_model(const io::CaseTable& root,
                                                 const io::SceneSettings& scene,
                                                 const materials::MaterialLibrary& materials,
                                                 std::optional<double> spare_particles = {});

/// A scene with [dem], [fem] and [coupling]: the grains, the shell parts, one DEM wall per
/// [[coupling.interface]] on the shell's mid-surface (named after its part or its `name`),
/// joined in one DemCoupledModel.
std::unique_ptr<DemCoupledModel>
read_dem_coupled_model(const io::CaseTable& root, const io::SceneSettings& scene,
                       const materials::MaterialLibrary& materials);

} // namespace grainload::coupling
