#pragma once

#include "io/types.hpp"

#include <vector>

namespace grainload::io {
class CaseTable;
}

namespace grainload::sph {

/// Particle centres filling one shape of a [[sph.body]] ([sph.body.shape] table) on a lattice of
/// the body's spacing. In 2D (plane strain) the lattice lies in the x-y plane with z = 0.
std::vector<Vec3> generate_body_points(const io::CaseTable& shape, double spacing, int dimension);

/// Points of a box [min, max] on a lattice whose cells have their centres inside the box.
std::vector<Vec3> fill_box(const Vec3& min, const Vec3& max, double spacing, int dimension);

} // namespace grainload::sph
