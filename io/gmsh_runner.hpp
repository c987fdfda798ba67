#pragma once
// Meshing a Gmsh geometry script with gmsh when its mesh is missing or outdated.

#include <string>
#include <utility>
#include <vector>

namespace grainload::io {

/// Numbers passed to Gmsh as `-setnumber NAME VALUE` (a .geo's DefineConstant values).
using GmshNumbers = std::vector<std::pair<std::string, double>>;

/// True when the mesh `msh` is missing, older than its geometry script `geo`, or was made
/// with other `numbers` than these (the stamp `msh.setnumber` beside it records them: a case
/// that changes its mesh size must not read the mesh of the old one).
bool gmsh_mesh_outdated(const std::string& geo, const std::string& msh,
                        const GmshNumbers& numbers = {});

/// Makes `msh` from the Gmsh geometry script `geo` when gmsh_mesh_outdated(): runs
/// `gmsh GEO -2 -format msh41 -o TMP` (the `gmsh` Debian package; the script sets its own mesh
/// options) and renames TMP onto `msh`, so a reader, a crash or a second run meshing the same
/// file at once never sees half a mesh. Gmsh's own failure (its exit status, an "Error" line,
/// no output) throws std::invalid_argument quoting Gmsh's error lines; so does a missing gmsh.
/// Returns true when it meshed.
/// `numbers` are passed as `-setnumber NAME VALUE` (the script's DefineConstant values, such
/// as a mesh size).
bool ensure_gmsh_mesh(const std::string& geo, const std::string& msh,
                      const GmshNumbers& numbers = {});

} // namespace grainload::io
