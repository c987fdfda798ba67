#pragma once
// Regions of space that particles can be in or out of: a half-space or a box.

#include "io/types.hpp"

namespace grainload::io {

/// A region of space that particles can be in or out of, independent of the method that moves
/// them (SPH particles now, DEM grains later): sinks and, later, sources use it.
///   half_space: the points beyond a plane, (x - point) . normal > 0 (normal points out of the
///   scene, into the region);
///   box: the axis-aligned box lower <= x <= upper (faces included); in plane strain (dimension
///   2) only x and y are tested.
struct Region {
    enum class Kind { half_space, box };
    Kind kind = Kind::half_space;
    Vec3 point = Vec3::Zero();
    Vec3 normal = Vec3::UnitZ(); ///< unit length
    Vec3 lower = Vec3::Zero();
    Vec3 upper = Vec3::Zero();
    int dimension = 3;

    static Region half_space(const Vec3& point, const Vec3& normal, int dimension);
    static Region box(const Vec3& lower, const Vec3& upper, int dimension);
    bool contains(const Vec3& x) const;
};

} // namespace grainload::io
