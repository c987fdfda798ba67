#pragma once
// The triangles of an STL file, ASCII or binary, as a SurfaceMesh.

#include "io/surface_mesh.hpp"

#include <string>

namespace grainload::io {

/// Triangles of an STL file, ASCII ("solid ... facet normal ... outer loop vertex x y z ...")
/// or binary (80-byte header, uint32 count, 50 bytes per triangle, little-endian float32).
/// The file is binary when its size is exactly 84 + 50 count bytes, whatever its header says
/// (binary exporters often start the header with "solid" too). The stored facet normals are
/// ignored: the vertex order defines the normal (right-hand rule). Vertices with identical
/// coordinates are merged, as STL repeats them per triangle. Throws std::invalid_argument
/// naming `name` and, for ASCII, the line.
SurfaceMesh read_stl(const std::string& bytes, const std::string& name);

} // namespace grainload::io
