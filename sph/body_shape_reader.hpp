#pragma once
// The shape of an SPH body or source as its [sph.body.shape] table states it, filled with
// particle centres.

#include "io/key_spec.hpp"
#include "io/types.hpp"
#include "sph/body_generator.hpp"

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// The keys of [sph.body.shape] (and of a source's [sph.source.shape]) but a mesh's
/// (io::kSurfaceMeshKeys) and a deck's (kKeywordBodyKeys).
inline constexpr std::array<io::KeySpec, 13> kShapeKeys{{
    {"type", "`box`, `cylinder`, `cone`, `mesh` or `lsdyna`", "", "the shape its lattice fills"},
    {"min", "length vector", "required for a box", "the box's lower corner"},
    {"max", "length vector", "required for a box", "the box's upper corner"},
    {"centre", "length vector", "required for a disc", "a 2D cylinder's centre"},
    {"base", "length vector", "required for a 3D cylinder or a cone",
     "the centre of the base face"},
    {"axis", "vector", "required for a 3D cylinder or a cone", "the direction base to top"},
    {"radius", "length", "required for a cylinder", "its radius"},
    {"height", "length", "required for a 3D cylinder or a cone", "along the axis"},
    {"base_radius", "length", "required for a cone", "the radius at the base"},
    {"top_radius", "length", "0 m", "the radius at the top: > 0 makes a frustum", 0.0},
    {"lattice", "`regular` or `jittered`", "regular",
     "jittered: each particle offset at random within its cell"},
    {"jitter", "number in [0, 0.5)", "0.1", "jittered: the largest offset per axis in spacings",
     0.1},
    {"seed", "integer", "1", "jittered: the same seed, the same particles", 1.0},
}};

/// The keys of each [[sph.body.shape.cut]]: the shape keeps the particles in front of a plane.
inline constexpr std::array<io::KeySpec, 3> kCutKeys{{
    {"point", "length vector", "", "a point of the plane"},
    {"normal", "vector", "", "towards the particles kept (any length)"},
    {"offset", "length", "0 m", "the particles kept are at least this far in front", 0.0},
}};

/// Particle centres filling one shape of a [[sph.body]] ([sph.body.shape] table: type = "box",
/// "cylinder", "cone" or "mesh" (a closed surface mesh, see closed_mesh_fill.hpp),
/// lattice = "regular" or "jittered") on a lattice of the body's spacing, or type = "lsdyna":
/// the *ELEMENT_SPH particles of a deck (keyword_body_reader.hpp), whose masses are checked against
/// the body's `density` [kg/m^3] * spacing^dimension.
/// In 2D (plane strain) the lattice lies in the x-y plane with z = 0. With `rounded`, the
/// axes along which the lattice (before any jitter) changed the shape's drawn size are added
/// to it (lattice_rounding).
std::vector<Vec3> generate_body_points(const io::CaseTable& shape, double spacing, int dimension,
                                       double density, std::vector<RoundedSize>* rounded = nullptr);

/// The drawn bounding box (lower, upper corner) of a box, cylinder or cone shape; none for a
/// shape cut by planes, a mesh or a deck, whose drawn extent the case does not state.
std::optional<std::pair<Vec3, Vec3>> drawn_bounds(const io::CaseTable& shape, int dimension);

/// [[sph.body.shape.cut]] tables (point, normal, offset): each keeps the points on the side its
/// normal points to, at least `offset` (default 0) from the plane, (x - point) . n >= offset, so a
/// box cut by planes fills a convex polyhedron (the load of a hopper or wagon above its slope
/// sheets).
void cut_points(const io::CaseTable& shape, std::vector<Vec3>& points, int dimension);

} // namespace grainload::sph
