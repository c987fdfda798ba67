#include "io/region.hpp"

#include <stdexcept>

namespace grainload::io {

Region Region::half_space(const Vec3& point, const Vec3& normal, int dimension) {
    if (!(normal.norm() > 0.0)) {
        throw std::invalid_argument("Region::half_space: the normal must not be zero");
    }
    Region region;
    region.kind = Kind::half_space;
    region.point = point;
    region.normal = normal.normalized();
    region.dimension = dimension;
    return region;
}

Region Region::box(const Vec3& lower, const Vec3& upper, int dimension) {
    for (int a = 0; a < dimension; ++a) {
        if (!(upper[a] > lower[a])) {
            throw std::invalid_argument("Region::box: expected upper > lower on every axis");
        }
    }
    Region region;
    region.kind = Kind::box;
    region.lower = lower;
    region.upper = upper;
    region.dimension = dimension;
    return region;
}

bool Region::contains(const Vec3& x) const {
    if (kind == Kind::half_space) {
        return (x - point).dot(normal) > 0.0;
    }
    for (int a = 0; a < dimension; ++a) {
        if (x[a] < lower[a] || x[a] > upper[a]) {
            return false;
        }
    }
    return true;
}

} // namespace grainload::io
