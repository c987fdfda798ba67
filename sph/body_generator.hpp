#pragma once
// Particle centres filling the shapes of an SPH body: box, cylinder, cone, mesh or LS-DYNA deck.

#include "io/types.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace grainload::sph {

/// A size of a shape that its lattice changed: along axis `axis` (0 x, 1 y, 2 z) the shape is
/// drawn `drawn` m long and its particles' cells (cubes of the spacing about the centres)
/// span `filled` m. A 40 mm cylinder at 3 mm is 13 cells, 39 mm, high.
struct RoundedSize {
    int axis = 0;
    double drawn = 0.0;
    double filled = 0.0;
};

/// The axes along which the cells of `points` span another length than [lower, upper], by
/// more than round-off (1e-6 of the spacing).
std::vector<RoundedSize> lattice_rounding(const std::pair<Vec3, Vec3>& drawn,
                                          const std::vector<Vec3>& points, double spacing,
                                          int dimension);

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
