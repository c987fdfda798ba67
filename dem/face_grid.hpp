#pragma once
// A uniform grid over a wall's faces: the faces a sphere at a point may touch, without a search
// over all of them.

#include "io/types.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace grainload::dem {

/// The faces of a wall binned in a uniform grid of cubic cells: each face is listed in every
/// cell its bounding box, grown by `reach`, overlaps; so a centre in a cell lies farther than
/// `reach` from every face the cell does not list. A mesh wall of thousands of triangles then
/// costs a sphere the few faces near it. Cells are at least `reach` wide and at most 64 to the
/// mesh's longest side; a centre outside the grid is farther than `reach` from every face.
class FaceGrid {
  public:
    struct Box {
        Vec3 min;
        Vec3 max;
    };

    /// Bins the faces' bounding boxes for spheres reaching `reach` from their centre.
    void build(std::span<const Box> faces, double reach);
    /// The reach the grid was built for; negative before build().
    double reach() const { return reach_; }
    /// The faces, in ascending order, that a sphere centred at `centre` may touch.
    std::span<const std::int32_t> near(const Vec3& centre) const;

  private:
    Vec3 origin_ = Vec3::Zero();
    Vec3 end_ = Vec3::Zero(); ///< the grid's upper corner
    double cell_ = 1.0;
    double per_cell_ = 1.0; ///< 1 / cell_
    std::array<std::int64_t, 3> dims_{0, 0, 0};
    std::vector<std::int64_t> first_; ///< per cell, its first entry in faces_ (CSR)
    std::vector<std::int32_t> faces_;
    double reach_ = -1.0;
};

} // namespace grainload::dem
