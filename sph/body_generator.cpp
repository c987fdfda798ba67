#include "sph/body_generator.hpp"

#include "io/case_table.hpp"
#include "sph/closed_mesh_fill.hpp"
#include "sph/keyword_body.hpp"

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

void cut_points(const io::CaseTable& shape, std::vector<Vec3>& points, int dimension) {
    namespace dim = io::dimension;
    for (const io::CaseTable& cut : shape.array_of_tables("cut")) {
        const Vec3 point = cut.vector("point", dim::kLength);
        Vec3 normal = cut.vector("normal", dim::kNone);
        if (dimension == 2) {
            normal.z() = 0.0;
        }
        if (!(normal.norm() > 0.0)) {
            cut.fail("normal", "expected a non-zero normal (towards the particles kept)");
        }
        normal.normalize();
        const double offset =
            cut.quantity_or("offset", dim::kLength, io::default_value(kCutKeys, "offset"));
        std::erase_if(points, [&](const Vec3& x) { return (x - point).dot(normal) < offset; });
        if (points.empty()) {
            cut.fail("normal", "the cut removes every particle of the shape: expected the "
                               "normal to point towards the particles kept");
        }
    }
}

std::vector<Vec3> generate_body_points(const io::CaseTable& shape, double spacing, int dimension,
                                       double density, std::vector<RoundedSize>* rounded) {
    namespace dim = io::dimension;
    const std::string type = shape.choice("type", {"box", "cylinder", "cone", "mesh", "lsdyna"});
    std::vector<Vec3> points;
    if (type == "lsdyna") {
        points = read_keyword_particles(shape, spacing, dimension, density);
    } else if (type == "mesh") {
        points = fill_mesh_shape(shape, spacing, dimension);
    } else if (type == "box") {
        const Vec3 min = shape.vector("min", dim::kLength);
        const Vec3 max = shape.vector("max", dim::kLength);
        for (int axis = 0; axis < dimension; ++axis) {
            if (!(max[axis] > min[axis])) {
                shape.fail("max", "expected max > min in every direction");
            }
        }
        points = fill_box(min, max, spacing, dimension);
    } else if (type == "cylinder" && dimension == 2) {
        points = fill_disc(shape.vector("centre", dim::kLength),
                           shape.positive_quantity("radius", dim::kLength), spacing, dimension);
    } else {
        const Vec3 base = shape.vector("base", dim::kLength);
        const Vec3 axis = shape.vector("axis", dim::kNone);
        Vec3 in_plane = axis;
        if (dimension == 2) {
            in_plane.z() = 0.0;
        }
        if (!(in_plane.norm() > 0.0)) {
            shape.fail("axis", "expected a non-zero axis direction");
        }
        const double height = shape.positive_quantity("height", dim::kLength);
        double base_radius = 0.0;
        double top_radius = 0.0;
        if (type == "cylinder") {
            base_radius = top_radius = shape.positive_quantity("radius", dim::kLength);
        } else {
            base_radius = shape.positive_quantity("base_radius", dim::kLength);
            top_radius = shape.quantity_or("top_radius", dim::kLength,
                                           io::default_value(kShapeKeys, "top_radius"));
            if (top_radius < 0.0) {
                shape.fail("top_radius", "expected a radius >= 0 (0: a full cone)");
            }
        }
        points = fill_cone(base, axis, base_radius, top_radius, height, spacing, dimension);
    }
    if (points.empty()) {
        shape.fail("type", "the shape holds no lattice cell centre: make it larger than the "
                           "spacing");
    }
    cut_points(shape, points, dimension);
    if (rounded != nullptr) {
        if (const auto drawn = drawn_bounds(shape, dimension)) {
            *rounded = lattice_rounding(*drawn, points, spacing, dimension);
        }
    }
    if (shape.choice_or("lattice", {"regular", "jittered"},
                        io::default_text(kShapeKeys, "lattice")) == "jittered") {
        const double fraction = shape.number_or("jitter", io::default_value(kShapeKeys, "jitter"));
        if (!(fraction >= 0.0 && fraction < 0.5)) {
            shape.fail("jitter", "expected a fraction of the spacing in [0, 0.5)");
        }
        const auto seed = shape.integer_or(
            "seed", static_cast<std::int64_t>(io::default_value(kShapeKeys, "seed")));
        jitter_points(points, spacing, fraction, static_cast<std::uint64_t>(seed), dimension);
    }
    return points;
}

std::optional<std::pair<Vec3, Vec3>> drawn_bounds(const io::CaseTable& shape, int dimension) {
    namespace dim = io::dimension;
    const std::string type = shape.string("type");
    if (shape.has("cut") || (type != "box" && type != "cylinder" && type != "cone")) {
        return std::nullopt;
    }
    if (type == "box") {
        return std::pair{shape.vector("min", dim::kLength), shape.vector("max", dim::kLength)};
    }
    if (type == "cylinder" && dimension == 2) {
        const Vec3 centre = shape.vector("centre", dim::kLength);
        const Vec3 reach = Vec3::Constant(shape.quantity("radius", dim::kLength));
        return std::pair{Vec3(centre - reach), Vec3(centre + reach)};
    }
    // A cylinder or cone: the bounding box of its end discs (segments in plane strain). A disc
    // of radius r normal to the unit axis a reaches r sqrt(1 - a_i^2) along axis i.
    Vec3 axis = shape.vector("axis", dim::kNone);
    if (dimension == 2) {
        axis.z() = 0.0;
    }
    axis.normalize();
    const Vec3 base = shape.vector("base", dim::kLength);
    const Vec3 top = base + shape.quantity("height", dim::kLength) * axis;
    const double base_radius = type == "cylinder" ? shape.quantity("radius", dim::kLength)
                                                  : shape.quantity("base_radius", dim::kLength);
    const double top_radius = type == "cylinder"
                                  ? base_radius
                                  : shape.quantity_or("top_radius", dim::kLength,
                                                      io::default_value(kShapeKeys, "top_radius"));
    Vec3 across;
    for (int i = 0; i < 3; ++i) {
        across[i] = std::sqrt(std::max(0.0, 1.0 - axis[i] * axis[i]));
    }
    const Vec3 lower = (base - base_radius * across).cwiseMin(top - top_radius * across);
    const Vec3 upper = (base + base_radius * across).cwiseMax(top + top_radius * across);
    return std::pair{lower, upper};
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
