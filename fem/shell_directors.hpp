#pragma once
// The initial directors of the shell elements' corners, split at the mesh's fold lines.

#include "fem/shell_mesh.hpp"

#include <array>
#include <vector>

namespace grainload::fem {

/// Initial directors of every element corner ("V_n^k" of Dvorkin & Bathe 1984), one array of
/// four per element in mesh order.
using ElementDirectors = std::vector<std::array<Vec3, 4>>;

/// Nodes on a fold line: where the normal of some element around the node deviates from the
/// (normalised) average of the element normals there by more than `mesh.fold_angle()`, or
/// where that average vanishes. Empty for meshes with exact normals (smooth generated
/// surfaces). Sorted by node id.
std::vector<Index> fold_nodes(const ShellMesh& mesh);

/// Initial element directors. At a smooth node every element gets the nodal normal of
/// `mesh.nodal_normals()` (so a mesh without folds is unchanged). At a fold node each element
/// gets the normalised average of the normals of the elements there that lie within the fold
/// angle of its own normal: its own face's normal on a box edge or corner, a smoothed normal
/// where a curved face meets the fold. All directors at a node rotate with the node's
/// rotation, so the 6 nodal DOFs stay compatible across the fold.
ElementDirectors element_directors(const ShellMesh& mesh);

} // namespace grainload::fem
