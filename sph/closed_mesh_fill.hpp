#pragma once
// The lattice cells inside a closed surface mesh, found by ray parity, for bodies of type "mesh".

#include "io/surface_mesh.hpp"

#include <vector>

namespace grainload::sph {

/// Edges of a triangle/quadrangle mesh counted by the faces that use them: a closed
/// (watertight) 2-manifold surface has every edge in exactly two faces.
struct EdgeUse {
    Index boundary = 0;     ///< edges in one face only: holes, or vertices not shared
    Index non_manifold = 0; ///< edges in three faces or more
};
EdgeUse count_edge_use(const io::SurfaceMesh& mesh);

/// Centres lower + spacing (i + 1/2, j + 1/2, k + 1/2) of the lattice cells, anchored at the
/// corner `lower` of the mesh's bounding box, that lie inside the closed surface (3D only;
/// quadrangles split along a diagonal). Inside is decided by ray parity along x: each row of
/// cells is crossed once with every face, and a cell centre is inside when an odd number of
/// crossings lie before it. A row through an edge or a vertex is counted once by the faces
/// around it: the point-in-triangle test in the y-z projection breaks ties as if the row
/// were moved by a fixed infinitesimal offset (simulation of simplicity, Edelsbrunner &
/// Muecke 1990), and each edge's test is evaluated once in a canonical direction, so two
/// faces sharing an edge always see the same sign. Throws std::runtime_error if a row still
/// has an odd number of crossings (a surface that is not closed).
std::vector<Vec3> fill_closed_mesh(const io::SurfaceMesh& mesh, double spacing);

} // namespace grainload::sph
