#include "sph/body_generator.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

namespace grainload::sph {

namespace {

/// Cell centres anchor + spacing (i + 1/2, j + 1/2, k + 1/2) inside [lower, upper] that pass
/// `inside`. Anchoring the lattice at a point of the shape (not at the bounding box) keeps it
/// symmetric about that point.
std::vector<Vec3> fill_where(const Vec3& anchor, const Vec3& lower, const Vec3& upper,
                             double spacing, int dimension,
                             const std::function<bool(const Vec3&)>& inside) {
    Eigen::Vector3i first = Eigen::Vector3i::Zero();
    Eigen::Vector3i last = Eigen::Vector3i::Zero();
    for (int axis = 0; axis < dimension; ++axis) {
        first[axis] = static_cast<int>(std::floor((lower[axis] - anchor[axis]) / spacing)) - 1;
        last[axis] = static_cast<int>(std::ceil((upper[axis] - anchor[axis]) / spacing)) + 1;
    }
    std::vector<Vec3> points;
    for (int k = first.z(); k <= last.z(); ++k) {
        for (int j = first.y(); j <= last.y(); ++j) {
            for (int i = first.x(); i <= last.x(); ++i) {
                Vec3 p = anchor + spacing * Vec3(i + 0.5, j + 0.5, k + 0.5);
                if (dimension == 2) {
                    p.z() = 0.0;
                }
                if (inside(p)) {
                    points.push_back(p);
                }
            }
        }
    }
    return points;
}

} // namespace

std::vector<Vec3> fill_box(const Vec3& min, const Vec3& max, double spacing, int dimension) {
    // Each particle represents a cell of volume spacing^dimension, so the cells tile the box
    // exactly when its edges are multiples of the spacing; otherwise the count rounds.
    Eigen::Vector3i count = Eigen::Vector3i::Ones();
    for (int axis = 0; axis < dimension; ++axis) {
        count[axis] = std::max(1, static_cast<int>(std::lround((max[axis] - min[axis]) / spacing)));
    }
    std::vector<Vec3> points;
    points.reserve(static_cast<std::size_t>(count.prod()));
    for (int k = 0; k < count.z(); ++k) {
        for (int j = 0; j < count.y(); ++j) {
            for (int i = 0; i < count.x(); ++i) {
                Vec3 p = min + spacing * Vec3(i + 0.5, j + 0.5, k + 0.5);
                if (dimension == 2) {
                    p.z() = 0.0;
                }
                points.push_back(p);
            }
        }
    }
    return points;
}

std::vector<Vec3> fill_cone(const Vec3& base, const Vec3& axis, double base_radius,
                            double top_radius, double height, double spacing, int dimension) {
    Vec3 a = axis;
    if (dimension == 2) {
        a.z() = 0.0;
    }
    a.normalize();
    const Vec3 top = base + height * a;
    const double r = std::max(base_radius, top_radius);
    const Vec3 reach = Vec3::Constant(r);
    const Vec3 lower = base.cwiseMin(top) - reach;
    const Vec3 upper = base.cwiseMax(top) + reach;
    return fill_where(base, lower, upper, spacing, dimension, [&](const Vec3& p) {
        const Vec3 d = p - base;
        const double s = d.dot(a);
        if (s < 0.0 || s > height) {
            return false;
        }
        const double radius = base_radius + (top_radius - base_radius) * s / height;
        return (d - s * a).norm() <= radius;
    });
}

std::vector<Vec3> fill_disc(const Vec3& centre, double radius, double spacing, int dimension) {
    const Vec3 reach = Vec3::Constant(radius);
    return fill_where(centre, centre - reach, centre + reach, spacing, dimension,
                      [&](const Vec3& p) {
                          Vec3 d = p - centre;
                          if (dimension == 2) {
                              d.z() = 0.0;
                          }
                          return d.norm() <= radius;
                      });
}

void jitter_points(std::vector<Vec3>& points, double spacing, double fraction, std::uint64_t seed,
                   int dimension) {
    std::mt19937_64 engine(seed);
    // The 53 high bits give a uniform double in [0, 1) without std::uniform_real_distribution,
    // whose algorithm is left to the library: this keeps runs identical across compilers.
    const auto uniform = [&engine] { return static_cast<double>(engine() >> 11) * 0x1.0p-53; };
    for (Vec3& p : points) {
        for (int axis = 0; axis < dimension; ++axis) {
            p[axis] += fraction * spacing * (2.0 * uniform() - 1.0);
        }
    }
}

std::vector<RoundedSize> lattice_rounding(const std::pair<Vec3, Vec3>& drawn,
                                          const std::vector<Vec3>& points, double spacing,
                                          int dimension) {
    std::vector<RoundedSize> rounded;
    if (points.empty()) {
        return rounded;
    }
    Vec3 low = points.front();
    Vec3 high = points.front();
    for (const Vec3& x : points) {
        low = low.cwiseMin(x);
        high = high.cwiseMax(x);
    }
    // The lattice's coordinates carry round-off of order 1e-16 of themselves; a rounding the
    // user can see is a fraction of the spacing.
    constexpr double kRoundOff = 1e-6;
    for (int a = 0; a < dimension; ++a) {
        const double length = drawn.second[a] - drawn.first[a];
        const double filled = high[a] - low[a] + spacing;
        if (std::abs(filled - length) > kRoundOff * spacing) {
            rounded.push_back({a, length, filled});
        }
    }
    return rounded;
}

std::string thin_body_warning(const std::vector<Vec3>& points, double spacing, int dimension,
                              const std::string& name) {
    // Three particles across fill the cubic spline's support (2.6 spacings) from a centre row.
    constexpr long kFewestAcross = 3;
    if (points.empty()) {
        return "";
    }
    Vec3 low = points.front();
    Vec3 high = points.front();
    for (const Vec3& x : points) {
        low = low.cwiseMin(x);
        high = high.cwiseMax(x);
    }
    for (int a = 0; a < dimension; ++a) {
        const long across = std::lround((high[a] - low[a]) / spacing) + 1;
        if (across < kFewestAcross) {
            return "body \"" + name + "\" is " + std::to_string(across) + " particle" +
                   (across == 1 ? "" : "s") + " across along " + std::string(1, "xyz"[a]) +
                   ": SPH needs about three across to fill its kernel support; halve the spacing "
                   "or thicken the body";
        }
    }
    return "";
}

} // namespace grainload::sph
