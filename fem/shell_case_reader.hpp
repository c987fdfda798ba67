#pragma once
// The readers of a case's [[fem.shell]] tables: mesh, parts, supports, loads, monitors.

#include "fem/shell_analysis.hpp"
#include "materials/material_library.hpp"

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::fem {

/// A displacement or rotation the case asks to report, with its optional reference.
struct ShellMonitor {
    std::string name;
    Index node = -1;
    int dof = 0;
    bool magnitude = false;
    std::optional<double> reference;
    std::string source;
};

/// A support reaction the case asks to report: the total force of the supports on the nodes of
/// a set (reaction_force summed), e.g. the vertical load a silo wall carries at its base.
struct ShellReaction {
    std::string name;
    std::vector<Index> nodes;
};

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
