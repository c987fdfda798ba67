#pragma once
// A surface mesh as read from a file: shared vertices and the faces that index them.

#include "io/types.hpp"

#include <array>
#include <vector>

namespace grainload::io {

/// A surface mesh as read from a file, before any use: shared vertices and the faces that
/// index them. Faces keep their vertex order, whose right-hand rule gives the face normal
/// (b - a) x (c - a); segments (plane-strain polylines) have the normal (-t_y, t_x) of their
/// tangent t = b - a, i.e. they face their left-hand side.
struct SurfaceMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<Index, 3>> triangles;
    std::vector<std::array<Index, 4>> quads;
    std::vector<std::array<Index, 2>> segments;
};

} // namespace grainload::io
