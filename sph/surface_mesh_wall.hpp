#pragma once
// The particles of a rigid wall laid in layers on a surface mesh.

#include "io/surface_mesh.hpp"
#include "sph/wall.hpp"

#include <vector>

namespace grainload::sph {

/// Particles of a rigid wall on a surface mesh (3D: its triangles and quadrangles; plane
/// strain: its line segments). Layer 0 lies on the surface: a triangle is subdivided
/// barycentrically from its vertex opposite the longest edge into n = ceil(longer of the two
/// other edges / spacing) parts per edge, a quadrangle bilinearly (ceil(longer of opposite
/// edges / spacing) parts each way), a segment into ceil(length / spacing) parts; every point
/// of a face is then within about spacing / sqrt(2) of a sample (exact for right triangles
/// and rectangles). Layer k (k = 1 .. layers - 1) repeats the samples k * spacing against
/// the face normal, which points into the material (right-hand rule of the vertex order, or
/// the left side of a segment; `flip_normals` reverses it). Samples of neighbouring faces
/// that coincide (shared edges and vertices) are merged: a sample closer than 0.3 spacing to
/// an earlier one is dropped, layer 0 first, so the surface keeps its samples and the layers
/// overlapping behind a convex edge are thinned.
/// The samples' origins (WallSample: face index counts the mesh's triangles, then its
/// quadrangles, or its segments in plane strain) come with the points.
struct MeshWallSamples {
    std::vector<Vec3> points;
    std::vector<WallSample> samples; ///< one per point
};
MeshWallSamples mesh_wall_points(const io::SurfaceMesh& mesh, double spacing, int layers,
                                 int dimension, bool flip_normals);

/// The samples mesh_wall_points lays before it merges coincident ones (an upper bound of its
/// points), counted in doubles without making any: a mesh of a few large faces at a fine
/// spacing may ask for more than memory or an int holds, which callers refuse first.
double mesh_wall_sample_bound(const io::SurfaceMesh& mesh, double spacing, int layers,
                              int dimension);

} // namespace grainload::sph
