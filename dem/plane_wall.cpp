#include "dem/plane_wall.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <map>
#include <utility>

namespace grainload::dem {

std::vector<PlaneWall::Face> PlaneWall::box_faces(const Vec3& min, const Vec3& max, int up,
                                                  bool open_top) {
    std::vector<Face> faces;
    for (int axis = 0; axis < 3; ++axis) {
        faces.push_back({min, Vec3::Unit(axis)});
        if (!(open_top && axis == up)) {
            faces.push_back({max, -Vec3::Unit(axis)});
        }
    }
    return faces;
}

void PlaneWall::set_mesh(const io::SurfaceMesh& mesh) {
    std::vector<std::array<Index, 3>> triangles(mesh.triangles.begin(), mesh.triangles.end());
    for (const auto& q : mesh.quads) {
        triangles.push_back({q[0], q[1], q[2]});
        triangles.push_back({q[0], q[2], q[3]});
    }
    faces.clear();
    for (const auto& t : triangles) {
        const Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
        const Vec3 e1 = mesh.vertices[static_cast<std::size_t>(t[1])] - a;
        const Vec3 e2 = mesh.vertices[static_cast<std::size_t>(t[2])] - a;
        faces.push_back({a, e1.cross(e2).normalized(), Shape::triangle, e1, e2});
    }
    // Neighbours through shared vertex indices: the readers merge a corner written alike.
    adjacent.assign(triangles.size(), {-1, -1, -1});
    std::map<std::pair<Index, Index>, std::int32_t> first_side;
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const Index u = triangles[f][static_cast<std::size_t>(k)];
            const Index v = triangles[f][static_cast<std::size_t>((k + 1) % 3)];
            const auto edge = std::minmax(u, v);
            const auto [at, inserted] = first_side.try_emplace(edge, static_cast<std::int32_t>(f));
            if (!inserted) {
                const auto other = static_cast<std::size_t>(at->second);
                adjacent[f][static_cast<std::size_t>(k)] = at->second;
                for (int m = 0; m < 3; ++m) {
                    const auto side =
                        std::minmax(triangles[other][static_cast<std::size_t>(m)],
                                    triangles[other][static_cast<std::size_t>((m + 1) % 3)]);
                    if (side == edge) {
                        adjacent[other][static_cast<std::size_t>(m)] = static_cast<std::int32_t>(f);
                    }
                }
            }
        }
    }
}

void PlaneWall::touching_faces(const Vec3& centre, double radius,
                               std::vector<Touch>& touched) const {
    touched.clear();
    Touch touch;
    if (!mesh()) {
        for (std::size_t f = 0; f < faces.size(); ++f) {
            if (touches(faces[f], centre, radius, touch.overlap, touch.normal)) {
                touch.face = static_cast<std::int32_t>(f);
                touched.push_back(touch);
            }
        }
        return;
    }
    for (const std::int32_t f : grid.near(centre)) {
        if (touches(faces[static_cast<std::size_t>(f)], centre, radius, touch.overlap,
                    touch.normal)) {
            touch.face = f;
            touched.push_back(touch);
        }
    }
    if (touched.size() < 2) {
        return;
    }
    std::sort(touched.begin(), touched.end(), [](const Touch& a, const Touch& b) {
        return a.overlap > b.overlap || (a.overlap == b.overlap && a.face < b.face);
    });
    // Behind a kept touch's tangent plane within round-off of the sphere's size: a shared edge
    // or corner is computed alike from either face, to a few ulps of the coordinates.
    const double slack = 1e-9 * radius;
    std::size_t kept = 0;
    for (const Touch& candidate : touched) {
        const Vec3 point = centre - (radius - candidate.overlap) * candidate.normal;
        bool behind = false;
        for (std::size_t k = 0; k < kept && !behind; ++k) {
            const Vec3 other = centre - (radius - touched[k].overlap) * touched[k].normal;
            behind = (point - other).dot(touched[k].normal) <= slack;
        }
        if (!behind) {
            touched[kept++] = candidate;
        }
    }
    touched.resize(kept);
    std::sort(touched.begin(), touched.end(),
              [](const Touch& a, const Touch& b) { return a.face < b.face; });
}

bool PlaneWall::touched_by(const Vec3& centre, double radius) const {
    double overlap = 0.0;
    Vec3 normal;
    const Vec3 at = centre - displacement;
    return std::any_of(faces.begin(), faces.end(), [&](const Face& face) {
        return touches(face, at, radius, overlap, normal);
    });
}

void PlaneWall::index_faces(double reach) {
    std::vector<FaceGrid::Box> boxes;
    boxes.reserve(faces.size());
    for (const Face& face : faces) {
        const Vec3 b = face.point + face.edge_u;
        const Vec3 c = face.point + face.edge_v;
        boxes.push_back({face.point.cwiseMin(b).cwiseMin(c), face.point.cwiseMax(b).cwiseMax(c)});
    }
    grid.build(boxes, reach);
}

} // namespace grainload::dem
