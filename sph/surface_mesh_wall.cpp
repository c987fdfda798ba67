#include "sph/surface_mesh_wall.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace grainload::sph {

namespace {

/// A surface sample, the unit normal of its face (right-hand rule) and where it lies on the
/// face (WallSample's face and parametric point).
struct Sample {
    Vec3 x;
    Vec3 normal;
    Index face;
    double r;
    double s;
};

/// Parts of an edge, in a double (mesh_wall_sample_bound counts edges beyond an int).
double part_count(double length, double spacing) {
    // The small allowance keeps an edge of exactly n spacings at n parts despite round-off.
    return std::max(1.0, std::ceil(length / spacing - 1e-9));
}

int parts(double length, double spacing) {
    return static_cast<int>(part_count(length, spacing));
}

/// Longest of the two edges from the vertex opposite the triangle's longest edge: the n of
/// sample_triangle is part_count of it.
double triangle_edge(const Vec3& x0, const Vec3& x1, const Vec3& x2) {
    std::array<double, 3> edge{(x2 - x1).norm(), (x0 - x2).norm(), (x1 - x0).norm()};
    std::sort(edge.begin(), edge.end());
    return edge[1];
}

/// Barycentric grid a + (i/n) ab + (j/n) ac, i + j <= n, from the vertex `a` opposite the
/// longest edge (vertices rotated, which keeps the normal), n = ceil(max(|ab|, |ac|) /
/// spacing): the sub-triangles have two edges of at most `spacing`, so every point is within
/// spacing / sqrt(2) of a sample (the right isosceles case), and a right triangle gets the
/// square lattice density 1 / spacing^2 rather than the 2 / spacing^2 that subdividing by
/// the longest edge would give.
void sample_triangle(const Vec3& x0, const Vec3& x1, const Vec3& x2, double spacing, Index face,
                     std::vector<Sample>& out) {
    std::array<Vec3, 3> x{x0, x1, x2};
    const std::array<double, 3> opposite{(x2 - x1).norm(), (x0 - x2).norm(), (x1 - x0).norm()};
    const auto first = static_cast<std::size_t>(std::max_element(opposite.begin(), opposite.end()) -
                                                opposite.begin());
    std::rotate(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(first), x.end());
    const Vec3 ab = x[1] - x[0], ac = x[2] - x[0];
    const int n = parts(triangle_edge(x0, x1, x2), spacing);
    const Vec3 normal = ab.cross(ac).normalized();
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; i + j <= n; ++j) {
            const double a = static_cast<double>(i) / n;
            const double b = static_cast<double>(j) / n;
            // Barycentric weights of the rotated vertices, back in the face's own order.
            std::array<double, 3> weight{};
            weight[first] = 1.0 - a - b;
            weight[(first + 1) % 3] = a;
            weight[(first + 2) % 3] = b;
            out.push_back({x[0] + a * ab + b * ac, normal, face, weight[1], weight[2]});
        }
    }
}

/// Bilinear patch x(s, t) = (1-s)(1-t) a + s(1-t) b + s t c + (1-s) t d; its normal is
/// x_s x x_t, constant for a planar parallelogram.
void sample_quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, double spacing,
                 Index face, std::vector<Sample>& out) {
    const int nu = parts(std::max((b - a).norm(), (c - d).norm()), spacing);
    const int nv = parts(std::max((d - a).norm(), (c - b).norm()), spacing);
    for (int j = 0; j <= nv; ++j) {
        const double t = static_cast<double>(j) / nv;
        for (int i = 0; i <= nu; ++i) {
            const double s = static_cast<double>(i) / nu;
            const Vec3 x = (1 - s) * (1 - t) * a + s * (1 - t) * b + s * t * c + (1 - s) * t * d;
            const Vec3 xs = (1 - t) * (b - a) + t * (c - d);
            const Vec3 xt = (1 - s) * (d - a) + s * (c - b);
            out.push_back({x, xs.cross(xt).normalized(), face, s, t});
        }
    }
}

void sample_segment(const Vec3& a, const Vec3& b, double spacing, Index face,
                    std::vector<Sample>& out) {
    const Vec3 t = b - a;
    const int n = parts(t.norm(), spacing);
    const Vec3 normal = Vec3(-t.y(), t.x(), 0.0).normalized();
    for (int i = 0; i <= n; ++i) {
        const double r = static_cast<double>(i) / n;
        out.push_back({a + r * t, normal, face, r, 0.0});
    }
}

std::vector<Sample> surface_samples(const io::SurfaceMesh& mesh, double spacing, int dimension) {
    const auto& v = mesh.vertices;
    std::vector<Sample> samples;
    Index face = 0;
    if (dimension == 2) {
        for (const auto& [a, b] : mesh.segments) {
            sample_segment(v[a], v[b], spacing, face++, samples);
        }
        return samples;
    }
    for (const auto& [a, b, c] : mesh.triangles) {
        sample_triangle(v[a], v[b], v[c], spacing, face++, samples);
    }
    for (const auto& [a, b, c, d] : mesh.quads) {
        sample_quad(v[a], v[b], v[c], v[d], spacing, face++, samples);
    }
    return samples;
}

/// Keeps a point only when no kept point lies within `radius`; a hash grid of cell size
/// `radius` finds the candidates in the 27 (3D) cells around it, so the merge is O(N).
class PointMerger {
  public:
    explicit PointMerger(double radius) : radius_(radius) {}

    /// True when x was kept.
    bool add(const Vec3& x) {
        const Key key = key_of(x);
        for (std::int64_t di = -1; di <= 1; ++di) {
            for (std::int64_t dj = -1; dj <= 1; ++dj) {
                for (std::int64_t dk = -1; dk <= 1; ++dk) {
                    const auto cell = cells_.find({key[0] + di, key[1] + dj, key[2] + dk});
                    if (cell == cells_.end()) {
                        continue;
                    }
                    for (const std::size_t k : cell->second) {
                        if ((points_[k] - x).norm() < radius_) {
                            return false;
                        }
                    }
                }
            }
        }
        cells_[key].push_back(points_.size());
        points_.push_back(x);
        return true;
    }

    std::vector<Vec3> take() { return std::move(points_); }

  private:
    using Key = std::array<std::int64_t, 3>;
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            // Large odd multipliers spread neighbouring cells over the buckets.
            return static_cast<std::size_t>(k[0] * 73856093LL ^ k[1] * 19349663LL ^
                                            k[2] * 83492791LL);
        }
    };
    Key key_of(const Vec3& x) const {
        return {static_cast<std::int64_t>(std::floor(x.x() / radius_)),
                static_cast<std::int64_t>(std::floor(x.y() / radius_)),
                static_cast<std::int64_t>(std::floor(x.z() / radius_))};
    }

    double radius_;
    std::vector<Vec3> points_;
    std::unordered_map<Key, std::vector<std::size_t>, KeyHash> cells_;
};

} // namespace

double mesh_wall_sample_bound(const io::SurfaceMesh& mesh, double spacing, int layers,
                              int dimension) {
    const auto& v = mesh.vertices;
    double count = 0.0;
    if (dimension == 2) {
        for (const auto& [a, b] : mesh.segments) {
            count += part_count((v[b] - v[a]).norm(), spacing) + 1.0;
        }
        return layers * count;
    }
    for (const auto& [a, b, c] : mesh.triangles) {
        const double n = part_count(triangle_edge(v[a], v[b], v[c]), spacing);
        count += (n + 1.0) * (n + 2.0) / 2.0; // i + j <= n
    }
    for (const auto& [a, b, c, d] : mesh.quads) {
        const double nu = part_count(std::max((v[b] - v[a]).norm(), (v[c] - v[d]).norm()), spacing);
        const double nv = part_count(std::max((v[d] - v[a]).norm(), (v[c] - v[b]).norm()), spacing);
        count += (nu + 1.0) * (nv + 1.0);
    }
    return layers * count;
}

MeshWallSamples mesh_wall_points(const io::SurfaceMesh& mesh, double spacing, int layers,
                                 int dimension, bool flip_normals) {
    const std::vector<Sample> samples = surface_samples(mesh, spacing, dimension);
    const int side = flip_normals ? -1 : 1;
    PointMerger merger(0.3 * spacing);
    MeshWallSamples wall;
    for (int layer = 0; layer < layers; ++layer) {
        const double offset = -side * layer * spacing;
        for (const Sample& s : samples) {
            if (merger.add(s.x + offset * s.normal)) {
                wall.samples.push_back({s.face, s.r, s.s, side, offset, layer});
            }
        }
    }
    wall.points = merger.take();
    return wall;
}

} // namespace grainload::sph
