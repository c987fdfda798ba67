#pragma once
// The readers of [fem] and [[fem.shell]]: mesh, parts, supports, loads, monitors.

#include "fem/shell_analysis.hpp"
#include "fem/shell_model.hpp"
#include "fem/time_function.hpp"
#include "io/key_spec.hpp"
#include "materials/material_library.hpp"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::fem {

/// The keys of the [fem] table (docs/user-guide/fem.md).
inline constexpr std::array<io::KeySpec, 15> kFemKeys{{
    {"analysis", "`static` or `dynamic`", "static",
     "static: load steps, time only orders them; dynamic: implicit Newmark or HHT-α"},
    {"kinematics", "`linear` or `total_lagrangian`", "linear",
     "small displacements, or large displacements and rotations with small strains"},
    {"load_time", "time", "`[case].end_time`",
     "when the load factor (a linear ramp, then held) reaches 1; it scales every load and "
     "prescribed value that names no `time_function`"},
    {"increments_per_step", "integer", "1", "load increments per time step (static)", 1.0},
    {"time_step", "time", "required when `dynamic`", "the implicit step of a dynamic analysis"},
    {"integrator", "`newmark` or `hht`", "newmark",
     "dynamic: Newmark, or Hilber–Hughes–Taylor α (damps high frequencies, second order)"},
    {"newmark_gamma", "number >= 0.5", "0.5",
     "`newmark`: γ; 0.5 is the energy-conserving trapezoidal rule, more damps high frequencies "
     "but is first order (β = (γ+½)²/4)",
     0.5},
    {"hht_alpha", "number in [-1/3, 0]", "-0.05",
     "`hht`: α; high-frequency spectral radius (1+α)/(1−α); 0 is the trapezoidal rule", -0.05},
    {"mass", "`lumped` or `consistent`", "lumped",
     "dynamic: diagonal mass, or the element mass matrix (frequencies converge from above, "
     "lumped from below)"},
    {"force_tolerance", "number", "1e-6",
     "ε_F of thesis eq. 5.2.8 (out-of-balance force ratio); <= 0 switches it off", 1e-6},
    {"energy_tolerance", "number", "1e-10",
     "ε_E of thesis eq. 5.2.9 (energy ratio); <= 0 switches it off", 1e-10},
    {"displacement_tolerance", "number", "0",
     "ε_U of thesis eq. 5.2.7 (displacement ratio); <= 0 switches it off", 0.0},
    {"max_iterations", "integer", "20", "Newton iterations per increment", 20.0},
    {"max_cutbacks", "integer", "6", "successive halvings of an increment that does not converge",
     6.0},
    {"seam_tolerance", "length", "10⁻⁶ × the largest part's size",
     "nodes of different parts closer than this are one node (the seam between the parts)", 1e-6},
}};

/// The keys of every [[fem.shell]] part, whatever its mesh source (docs/user-guide/fem.md).
inline constexpr std::array<io::KeySpec, 8> kShellKeys{{
    {"name", "string", "`\"shell\"` (one part only)",
     "the part's name: its block in the output frames, how [[coupling.interface]] names it; "
     "unique"},
    {"offset", "length vector", "none",
     "moves the part's mesh after it is generated or read (a hopper placed below its silo)"},
    {"material", "string", "", "a [[material]] name (any model; plane stress is derived)"},
    {"thickness", "length", "required, but for `lsdyna` and `gmsh` with groups",
     "the shell's thickness (`gmsh`: of the elements in no [[fem.shell.group]])"},
    {"thickness_points", "integer", "2 linear elastic, 5 otherwise",
     "Gauss points through the thickness, 2 to 15"},
    {"generator", "string", "",
     "the mesh source: `plate`, `cylinder`, `sphere_zone`, `cone`, `box`, `gmsh` or `lsdyna`"},
    {"fold_angle", "angle", "`\"20 deg\"`",
     "a node where an element normal deviates from the mean normal by more than this is on a "
     "fold line, where each element keeps its own director; in (0, 180] deg",
     ShellMesh::kDefaultFoldAngle},
    {"file", "string", "required for `gmsh` and `lsdyna`",
     "the Gmsh `.msh` or the LS-DYNA deck, relative to the case file"},
}};

/// The keys of the generated meshes (plate, cylinder, sphere_zone, cone, box), each read by the
/// generators the user guide names with it.
inline constexpr std::array<io::KeySpec, 19> kShellGeneratorKeys{{
    {"length_x", "length", "", "`plate`, `box`: the extent along x"},
    {"length_y", "length", "", "`plate`, `box`: the extent along y"},
    {"height", "length", "", "`cone`, `box`: the extent along z"},
    {"elements_x", "integer", "", "`plate`, `box`: elements along x"},
    {"elements_y", "integer", "", "`plate`, `box`: elements along y"},
    {"elements_z", "integer", "", "`box`: elements along z"},
    {"top", "`open` or `closed`", "open", "`box`: whether it has its top face"},
    {"radius", "length", "", "`cylinder`, `sphere_zone`: the radius"},
    {"length", "length", "", "`cylinder`: the length along its axis y"},
    {"angle_start", "angle", "", "`cylinder`: the first generator line's angle φ"},
    {"angle_end", "angle", "", "`cylinder`: the last generator line's angle φ"},
    {"elements_around", "integer", "", "`cylinder`, `sphere_zone`, `cone`: elements around"},
    {"elements_along", "integer", "", "`cylinder`, `cone`: elements along the axis"},
    {"polar_start", "angle", "", "`sphere_zone`: the polar angle where the zone starts"},
    {"polar_end", "angle", "", "`sphere_zone`: the polar angle where the zone ends"},
    {"azimuth_end", "angle", "", "`sphere_zone`, `cone`: the azimuth the part spans from 0"},
    {"elements_polar", "integer", "", "`sphere_zone`: elements along the meridian"},
    {"radius_bottom", "length", "", "`cone`: the radius at z = 0"},
    {"radius_top", "length", "", "`cone`: the radius at z = height (0: a full cone)"},
}};

/// The keys of each [[fem.shell.boundary]] table.
inline constexpr std::array<io::KeySpec, 10> kBoundaryKeys{{
    {"node_set", "string", "required unless `point`",
     "the constrained node set (the part's first)"},
    {"point", "length vector", "none", "instead of `node_set`: the node nearest to it"},
    {"symmetry", "`x`, `y` or `z`", "none",
     "a symmetry plane of that normal: fixes the normal translation and the two rotations in the "
     "plane"},
    {"dofs", "string", "required unless `symmetry` or `angle`",
     "the prescribed DOFs, any of `ux uy uz rx ry rz`, or `all`"},
    {"displacement", "length", "`\"0 m\"`", "the value of the prescribed translations", 0.0},
    {"rotation", "angle", "`\"0 deg\"`",
     "the value of the prescribed rotations (global rotation-vector components)", 0.0},
    {"axis", "vector", "required with `angle`", "the direction of a rigid rotation's axis"},
    {"axis_point", "length vector", "`\"0 0 0 m\"`", "a point on a rigid rotation's axis"},
    {"angle", "angle", "none", "a rigid rotation of the nodes about `axis` by this angle"},
    {"time_function", "string", "the load ramp", "a [[fem.time_function]] scaling the values"},
}};

/// The keys of each [[fem.shell.load]] table.
inline constexpr std::array<io::KeySpec, 7> kLoadKeys{{
    {"type", "string", "", "`area_force`, `pressure`, `gravity`, `nodal_force` or `nodal_moment`"},
    {"value", "pressure, pressure vector, force or moment vector", "required but for `gravity`",
     "the load: per unit area (`area_force`, `pressure`) or per node"},
    {"follower", "boolean", "false",
     "`pressure`: acts normal to the deformed surface on its deformed area", 0.0},
    {"acceleration", "acceleration vector", "`[case].gravity`",
     "`gravity`: the acceleration of the shell's mass"},
    {"node_set", "string", "required for nodal loads unless `point`",
     "the loaded nodes (the part's set first)"},
    {"point", "length vector", "none", "nodal loads: the node nearest to it instead of `node_set`"},
    {"time_function", "string", "the load ramp", "a [[fem.time_function]] scaling the load"},
}};

/// The keys of each [[fem.shell.monitor]] table.
inline constexpr std::array<io::KeySpec, 6> kMonitorKeys{{
    {"name", "string", "", "the figure's name in summary.json"},
    {"point", "length vector", "", "the node nearest to it is reported"},
    {"dof", "string", "", "one of `ux uy uz rx ry rz`"},
    {"magnitude", "boolean", "false", "report the absolute value", 0.0},
    {"reference", "length or angle", "none", "a reference value reported beside it"},
    {"source", "string", "none", "where the reference comes from"},
}};

/// The keys of each [[fem.shell.reaction]] table.
inline constexpr std::array<io::KeySpec, 2> kReactionKeys{{
    {"name", "string", "", "the figures' name: `<name>_x`, `<name>_y`, `<name>_z` in summary.json"},
    {"node_set", "string", "",
     "a node set of the part (constrained nodes; elsewhere the reaction is zero)"},
}};

/// The keys of each [[fem.time_function]] table.
inline constexpr std::array<io::KeySpec, 4> kTimeFunctionKeys{{
    {"name", "string", "", "referenced by `time_function` in loads and boundary conditions"},
    {"type", "`points` or `ramp`", "points", "piecewise linear through `points`, or a ramp"},
    {"points", "list of [time, number] pairs", "required for `points`",
     "f(t) piecewise linear, times increasing, held at the end values outside them"},
    {"ramp_time", "time", "required for `ramp`", "f = min(t / ramp_time, 1)"},
}};

/// The case's [[fem.time_function]] tables by name (see docs/user-guide/fem.md).
std::map<std::string, TimeFunction> read_time_functions(const io::CaseTable& fem);

/// Mesh of one [[fem.shell]] table from its `generator` keys (see docs/user-guide/fem.md).
ShellMesh read_shell_mesh(const io::CaseTable& shell);

/// The structure of every [[fem.shell]] table of [fem]: one mesh whose elements carry their
/// part (the table's index), the parts' materials and integration points. Parts meet where
/// their nodes coincide within [fem] `seam_tolerance` (default 1e-6 of the structure's size).
/// Each part's node and element sets are named "<part>.<set>" and, when no earlier part has
/// a set of that name, "<set>". Part names are unique.
std::pair<ShellMesh, std::vector<ShellPart>>
read_shell_parts(const io::CaseTable& fem, const std::vector<io::CaseTable>& shells,
                 const materials::MaterialLibrary& materials);

/// The part whose tables are read: sets are looked up as "<name>.<set>" first.
struct PartScope {
    int index = 0;
    std::string name;
};

/// Load histories of the analysis by time-function name, for the `time_function` keys.
using HistoryNames = std::map<std::string, int>;
/// Applies its [[fem.shell.boundary]] tables to `analysis`.
void read_shell_boundaries(const io::CaseTable& shell, const HistoryNames& histories,
                           const PartScope& part, ShellAnalysis& analysis);
/// Adds its [[fem.shell.load]] tables to the loads of their histories (history 0, the load
/// factor, unless a table names a `time_function`); distributed loads act on the part's
/// elements only.
void read_shell_loads(const io::CaseTable& shell, const Vec3& case_gravity,
                      const HistoryNames& histories, const PartScope& part,
                      ShellAnalysis& analysis);
std::vector<ShellMonitor> read_shell_monitors(const io::CaseTable& shell, const ShellMesh& mesh);
/// Its [[fem.shell.reaction]] tables: `name` and `node_set` (the part's sets first).
std::vector<ShellReaction> read_shell_reactions(const io::CaseTable& shell, const ShellMesh& mesh,
                                                const PartScope& part);
/// "ux" .. "rz" -> 0 .. 5; a CaseError names the key otherwise.
int read_dof(const io::CaseTable& table, std::string_view key, const std::string& name);

} // namespace grainload::fem
