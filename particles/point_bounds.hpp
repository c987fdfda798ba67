#pragma once
// The axis-aligned box of a set of points, reduced over the threads.

#include "io/types.hpp"

#include <algorithm>
#include <limits>
#include <span>

namespace grainload::particles {

/// Axis-aligned box of a set of points; empty (lower = +inf, upper = -inf) when none was taken.
struct PointBounds {
    Vec3 lower = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 upper = Vec3::Constant(-std::numeric_limits<double>::infinity());
    bool empty() const { return !(lower.x() <= upper.x()); }
};

/// The box of the points x[i] that `take(i)` admits, reduced over the threads: minima and
/// maxima are exact in any order, so it is the serial scan's box. For the scans that run every
/// step (the cell grid, the escape watch).
template <class Take> PointBounds point_bounds(std::span<const Vec3> x, Take take) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    double lx = kInf, ly = kInf, lz = kInf, ux = -kInf, uy = -kInf, uz = -kInf;
    const auto n = static_cast<Index>(x.size());
#pragma omp parallel for schedule(static) reduction(min : lx, ly, lz) reduction(max : ux, uy, uz)
    for (Index i = 0; i < n; ++i) {
        if (take(i)) {
            lx = std::min(lx, x[i][0]);
            ly = std::min(ly, x[i][1]);
            lz = std::min(lz, x[i][2]);
            ux = std::max(ux, x[i][0]);
            uy = std::max(uy, x[i][1]);
            uz = std::max(uz, x[i][2]);
        }
    }
    PointBounds box;
    box.lower = Vec3(lx, ly, lz);
    box.upper = Vec3(ux, uy, uz);
    return box;
}

} // namespace grainload::particles
