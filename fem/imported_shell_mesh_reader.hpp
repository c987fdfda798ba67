#pragma once
// The mesh of a [[fem.shell]] imported from a Gmsh mesh or an LS-DYNA keyword deck.

#include "fem/shell_mesh.hpp"
#include "io/key_spec.hpp"

#include <array>
#include <string>

namespace grainload::io {
class CaseTable;
}

namespace grainload::fem {

/// The keys of a [[fem.shell]] with generator = "gmsh" besides `file` and `thickness`.
inline constexpr std::array<io::KeySpec, 2> kGmshKeys{{
    {"geo", "string", "none",
     "a Gmsh geometry script that makes `file` (`gmsh GEO -2`) when it is missing or older"},
    {"geo_numbers", "table of numbers", "none",
     "values of the script's `DefineConstant`s (`gmsh -setnumber NAME VALUE`)"},
}};

/// The keys of a [[fem.shell]] with generator = "lsdyna" besides `file`.
inline constexpr std::array<io::KeySpec, 2> kKeywordShellKeys{{
    {"units", "string", "", "the deck's consistent unit system, `\"LENGTH-MASS-TIME\"`"},
    {"parts", "string, integer or a list of them", "every part with shell elements",
     "the *PARTs that make the shell: titles or ids"},
}};

/// The keys of each [[fem.shell.group]] table: a physical surface of a Gmsh mesh.
inline constexpr std::array<io::KeySpec, 2> kShellGroupKeys{{
    {"name", "string", "", "a physical surface of the mesh"},
    {"thickness", "length", "", "the thickness of its elements"},
}};

/// Mesh of a [[fem.shell]] whose generator is "gmsh" (a Gmsh .msh, made first from its `geo`
/// script when that is newer, with per-group thicknesses from [[fem.shell.group]]) or "lsdyna"
/// (the shell parts of an LS-DYNA keyword deck in the stated `units`). Keys and defaults:
/// docs/user-guide/fem.md. Bad input throws io::CaseError at the key concerned; the keywords of
/// a deck that grainload does not read are listed in one warning on stderr.
ShellMesh read_imported_shell_mesh(const io::CaseTable& shell, const std::string& generator);

} // namespace grainload::fem
