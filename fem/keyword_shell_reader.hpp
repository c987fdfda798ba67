#pragma once
// The shell mesh of chosen parts of an LS-DYNA deck, its parts and sets as named sets.

#include "fem/shell_mesh.hpp"
#include "io/keyword_mesh.hpp"

#include <string>
#include <vector>

namespace grainload::fem {

/// The shell mesh of the parts `parts` of an LS-DYNA deck (each a *PART title or id; empty:
/// every part with shell elements). Nodes are those the selected elements use, in *NODE order;
/// elements in *ELEMENT_SHELL order. An element's thickness is the mean of its nodal
/// thicknesses (*ELEMENT_SHELL_THICKNESS THIC1..4 where given, else its part's *SECTION_SHELL
/// T1..T4; triangles use three), as the MITC4 element has one thickness. Named sets: each part
/// an element set and a node set under its title (untitled: "part<PID>"); each *SET_NODE_LIST
/// a node set and each *SET_SHELL_LIST an element set under its title (untitled: "set<SID>"),
/// holding the members in the mesh (sets with none are left out). Throws io::KeywordError for
/// an unknown part, a part without a *SECTION_SHELL, or two sets of one name.
ShellMesh make_keyword_shell_mesh(const io::KeywordMesh& deck,
                                  const std::vector<std::string>& parts);

} // namespace grainload::fem
