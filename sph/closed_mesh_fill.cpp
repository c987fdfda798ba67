#include "sph/closed_mesh_fill.hpp"

#include "io/surface_mesh_reader.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>

namespace grainload::sph {

namespace {

using Vec2 = Eigen::Vector2d;

double cross(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

/// Edge function of the directed edge a -> b at q (positive: q on its left). It is evaluated
/// from the lexicographically smaller end, so the faces on both sides of an edge get exactly
/// opposite values and never disagree on which side q is.
double edge_function(const Vec2& a, const Vec2& b, const Vec2& q) {
    const bool canonical = a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    return canonical ? cross(b - a, q - a) : -cross(a - b, q - b);
}

/// Whether a point exactly on the edge a -> b of a counter-clockwise triangle counts as
/// inside: it does when moving it by the fixed infinitesimal offset (1, -eta) takes it
/// inside. Of the two opposite directions of an edge exactly one passes, so a shared edge
/// belongs to one face, and around a vertex exactly one face of a fan takes the point.
bool owns_boundary(const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    return d.y() < 0.0 || (d.y() == 0.0 && d.x() < 0.0);
}

/// When q is inside the counter-clockwise triangle p (edges owned by the tie rule above):
/// the edge functions of the edges opposite each vertex, i.e. q's barycentric weights times
/// twice the area.
std::optional<std::array<double, 3>> inside_weights(const std::array<Vec2, 3>& p, const Vec2& q) {
    std::array<double, 3> w{};
    for (std::size_t e = 0; e < 3; ++e) {
        const Vec2& a = p[(e + 1) % 3];
        const Vec2& b = p[(e + 2) % 3];
        w[e] = edge_function(a, b, q);
        if (!(w[e] > 0.0 || (w[e] == 0.0 && owns_boundary(a, b)))) {
            return std::nullopt;
        }
    }
    return w;
}

/// The rows of lattice cells along x: row (j, k) has the y-z centre q(j, k) and collects the
/// x of its crossings with the surface.
class RowCrossings {
  public:
    RowCrossings(const Vec3& lower, const Vec3& upper, double spacing)
        : lower_(lower), spacing_(spacing) {
        for (int axis = 0; axis < 3; ++axis) {
            count_[axis] =
                std::max(1, static_cast<int>(std::ceil((upper[axis] - lower[axis]) / spacing)));
        }
        rows_.resize(static_cast<std::size_t>(count_[1]) * static_cast<std::size_t>(count_[2]));
    }

    /// Record where the rows whose centre falls inside the triangle cross it.
    void add_triangle(const Vec3& x0, const Vec3& x1, const Vec3& x2) {
        std::array<Vec3, 3> x{x0, x1, x2};
        std::array<Vec2, 3> p{x0.tail<2>(), x1.tail<2>(), x2.tail<2>()};
        const double area = cross(p[1] - p[0], p[2] - p[0]);
        if (area == 0.0) {
            return; // parallel to x: the rows run along it, the neighbours count
        }
        if (area < 0.0) {
            std::swap(p[1], p[2]);
            std::swap(x[1], x[2]);
        }
        const Vec2 low = p[0].cwiseMin(p[1]).cwiseMin(p[2]);
        const Vec2 high = p[0].cwiseMax(p[1]).cwiseMax(p[2]);
        const auto [j0, j1] = row_range(low.x(), high.x(), 1);
        const auto [k0, k1] = row_range(low.y(), high.y(), 2);
        for (int k = k0; k <= k1; ++k) {
            for (int j = j0; j <= j1; ++j) {
                const Vec2 q(centre(j, 1), centre(k, 2));
                const auto w = inside_weights(p, q);
                if (w) {
                    const auto& [w0, w1, w2] = *w;
                    row(j, k).push_back((w0 * x[0].x() + w1 * x[1].x() + w2 * x[2].x()) /
                                        (w0 + w1 + w2));
                }
            }
        }
    }

    /// The cell centres inside: odd number of crossings before them along the row.
    std::vector<Vec3> inside_points() {
        std::vector<Vec3> points;
        for (int k = 0; k < count_[2]; ++k) {
            for (int j = 0; j < count_[1]; ++j) {
                auto& crossings = row(j, k);
                if (crossings.size() % 2 != 0) {
                    throw std::runtime_error(
                        "ray parity: the row at y = " + std::to_string(centre(j, 1)) +
                        " m, z = " + std::to_string(centre(k, 2)) + " m crosses the surface " +
                        std::to_string(crossings.size()) + " times (odd): it is not closed");
                }
                std::sort(crossings.begin(), crossings.end());
                std::size_t before = 0;
                for (int i = 0; i < count_[0]; ++i) {
                    const double x = centre(i, 0);
                    while (before < crossings.size() && crossings[before] < x) {
                        ++before;
                    }
                    if (before % 2 == 1) {
                        points.emplace_back(x, centre(j, 1), centre(k, 2));
                    }
                }
            }
        }
        return points;
    }

  private:
    double centre(int index, int axis) const { return lower_[axis] + (index + 0.5) * spacing_; }
    /// Rows whose centre may lie in [low, high], one more each side against round-off: the
    /// point-in-triangle test decides.
    std::pair<int, int> row_range(double low, double high, int axis) const {
        const int first = static_cast<int>(std::floor((low - lower_[axis]) / spacing_ - 0.5));
        const int last = static_cast<int>(std::ceil((high - lower_[axis]) / spacing_ - 0.5));
        return {std::max(0, first - 1), std::min(count_[axis] - 1, last + 1)};
    }
    std::vector<double>& row(int j, int k) {
        return rows_[static_cast<std::size_t>(k) * static_cast<std::size_t>(count_[1]) +
                     static_cast<std::size_t>(j)];
    }

    Vec3 lower_;
    double spacing_;
    std::array<int, 3> count_{};
    std::vector<std::vector<double>> rows_;
};

} // namespace

EdgeUse count_edge_use(const io::SurfaceMesh& mesh) {
    std::map<std::pair<Index, Index>, int> uses;
    const auto add = [&uses](Index a, Index b) { ++uses[{std::min(a, b), std::max(a, b)}]; };
    for (const auto& [a, b, c] : mesh.triangles) {
        add(a, b), add(b, c), add(c, a);
    }
    for (const auto& [a, b, c, d] : mesh.quads) {
        add(a, b), add(b, c), add(c, d), add(d, a);
    }
    EdgeUse count;
    for (const auto& [edge, n] : uses) {
        count.boundary += n == 1 ? 1 : 0;
        count.non_manifold += n > 2 ? 1 : 0;
    }
    return count;
}

std::vector<Vec3> fill_closed_mesh(const io::SurfaceMesh& mesh, double spacing) {
    const auto& v = mesh.vertices;
    Vec3 lower = v.front(), upper = v.front();
    for (const Vec3& x : v) {
        lower = lower.cwiseMin(x);
        upper = upper.cwiseMax(x);
    }
    RowCrossings rows(lower, upper, spacing);
    for (const auto& [a, b, c] : mesh.triangles) {
        rows.add_triangle(v[a], v[b], v[c]);
    }
    for (const auto& [a, b, c, d] : mesh.quads) {
        rows.add_triangle(v[a], v[b], v[c]);
        rows.add_triangle(v[a], v[c], v[d]);
    }
    return rows.inside_points();
}

} // namespace grainload::sph
