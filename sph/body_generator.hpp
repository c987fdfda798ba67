#pragma once
// Particle centres filling the shapes of an SPH body: box, cylinder, cone, mesh or LS-DYNA deck.

#include "io/key_spec.hpp"
#include "io/types.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
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

/// A size of a shape that its lattice changed: along axis `axis` (0 x, 1 y, 2 z) the shape is
/// drawn `drawn` m long and its particles' cells (cubes of the spacing about the centres)
/// span `filled` m. A 40 mm cylinder at 3 mm is 13 cells, 39 mm, high.
struct RoundedSize {
    int axis = 0;
    double drawn = 0.0;
    double filled = 0.0;
};

/// Particle centres filling one shape of a [[sph.body]] ([sph.body.shape] table: type = "box",
/// "cylinder", "cone" or "mesh" (a closed surface mesh, see closed_mesh_fill.hpp),
/// lattice = "regular" or "jittered") on a lattice of the body's spacing, or type = "lsdyna":
/// the *ELEMENT_SPH particles of a deck (keyword_body.hpp), whose masses are checked against
/// the body's `density` [kg/m^3] * spacing^dimension.
/// In 2D (plane strain) the lattice lies in the x-y plane with z = 0. With `rounded`, the
/// axes along which the lattice (before any jitter) changed the shape's drawn size are added
/// to it (lattice_rounding).
std::vector<Vec3> generate_body_points(const io::CaseTable& shape, double spacing, int dimension,
                                       double density, std::vector<RoundedSize>* rounded = nullptr);

/// The drawn bounding box (lower, upper corner) of a box, cylinder or cone shape; none for a
/// shape cut by planes, a mesh or a deck, whose drawn extent the case does not state.
std::optional<std::pair<Vec3, Vec3>> drawn_bounds(const io::CaseTable& shape, int dimension);

/// The axes along which the cells of `points` span another length than [lower, upper], by
/// more than round-off (1e-6 of the spacing).
std::vector<RoundedSize> lattice_rounding(const std::pair<Vec3, Vec3>& drawn,
                                          const std::vector<Vec3>& points, double spacing,
                                          int dimension);

/// [[sph.body.shape.cut]] tables (point, normal, offset): each keeps the points on the side its
/// normal points to, at least `offset` (default 0) from the plane, (x - point) . n >= offset, so a
/// box cut by planes fills a convex polyhedron (the load of a hopper or wagon above its slope
/// sheets).
void cut_points(const io::CaseTable& shape, std::vector<Vec3>& points, int dimension);

/// Points of a box [min, max] on a lattice whose cells have their centres inside the box.
std::vector<Vec3> fill_box(const Vec3& min, const Vec3& max, double spacing, int dimension);

/// Centres of the lattice cells inside a (truncated) cone: the circle of radius `base_radius`
/// about `base`, normal to `axis`, swept `height` along `axis` while the radius goes linearly to
/// `top_radius` (equal radii: a cylinder; 0: a full cone). The lattice is aligned with x, y, z
/// and has a cell corner at `base`, so a shape whose axis is a coordinate axis is filled
/// symmetrically about it. In 2D the shape is the x-y section through the axis (a trapezoid).
std::vector<Vec3> fill_cone(const Vec3& base, const Vec3& axis, double base_radius,
                            double top_radius, double height, double spacing, int dimension);

/// Centres of the lattice cells inside the disc (2D) or ball (3D) of `radius` about `centre`.
std::vector<Vec3> fill_disc(const Vec3& centre, double radius, double spacing, int dimension);

/// Move every point by an independent uniform offset in [-fraction, fraction] * spacing per
/// in-plane axis. With fraction < 1/2 each particle stays in its own lattice cell, so its
/// volume spacing^dimension still stands for that cell. Same seed, same points: the generator
/// is std::mt19937_64, whose sequence the C++ standard fixes.
void jitter_points(std::vector<Vec3>& points, double spacing, double fraction, std::uint64_t seed,
                   int dimension);

/// A warning when a body is fewer than three particles across along one of its axes (its
/// bounding box; "" otherwise): the SPH sums need the kernel support, 2h = 2.6 spacings at the
/// default h = 1.3 dp, filled across the body, so a layer one or two particles thick has
/// spurious surface deficiency everywhere (docs/theory/sph.md).
std::string thin_body_warning(const std::vector<Vec3>& points, double spacing, int dimension,
                              const std::string& name);

} // namespace grainload::sph
