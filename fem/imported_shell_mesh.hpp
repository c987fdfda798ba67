#pragma once
// The mesh of a [[fem.shell]] imported from a Gmsh mesh or an LS-DYNA keyword deck.

#include "fem/shell_mesh.hpp"

#include <string>

namespace grainload::io {
class CaseTable;
}

namespace grainload::fem {

/// Mesh of a [[fem.shell]] whose generator is "gmsh" (a Gmsh .msh, made first from its `geo`
/// script when that is newer, with per-group thicknesses from [[fem.shell.group]]) or "lsdyna"
/// (the shell parts of an LS-DYNA keyword deck in the stated `units`). Keys and defaults:
/// docs/user-guide/fem.md. Bad input throws io::CaseError at the key concerned; the keywords of
/// a deck that grainload does not read are listed in one warning on stderr.
ShellMesh read_imported_shell_mesh(const io::CaseTable& shell, const std::string& generator);

} // namespace grainload::fem
