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
    vertices.corners.clear();
    for (const auto& t : triangles) {
        vertices.corners.push_back({static_cast<std::int32_t>(t[0]),
                                    static_cast<std::int32_t>(t[1]),
                                    static_cast<std::int32_t>(t[2])});
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
        return touches(face, at, radius + half_thickness, overlap, normal);
    });
}

void PlaneWall::index_faces(double reach) {
    std::vector<FaceGrid::Box> boxes;
    boxes.reserve(faces.size());
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const Face& face = faces[f];
        const Vec3 b = face.point + face.edge_u;
        const Vec3 c = face.point + face.edge_v;
        FaceGrid::Box box{face.point.cwiseMin(b).cwiseMin(c), face.point.cwiseMax(b).cwiseMax(c)};
        if (follows()) {
            for (const std::int32_t k : vertices.corners[f]) {
                for (const auto* at : {&vertices.start, &vertices.end}) {
                    box.min = box.min.cwiseMin((*at)[static_cast<std::size_t>(k)]);
                    box.max = box.max.cwiseMax((*at)[static_cast<std::size_t>(k)]);
                }
            }
        }
        boxes.push_back(box);
    }
    grid.build(boxes, reach);
}

void PlaneWall::set_interval(const std::vector<Vec3>& end, double start_time, double end_time) {
    vertices.start = vertices.end.empty() ? end : vertices.end;
    vertices.end = end;
    vertices.start_time = start_time;
    vertices.end_time = end_time;
    vertices.force.assign(end.size(), Vec3::Zero());
    vertices.moment.assign(end.size(), Vec3::Zero());
    // The faces sweep a new region: the contact pass bins them anew.
    grid = FaceGrid{};
}

void PlaneWall::follow(double time) {
    const double length = vertices.end_time - vertices.start_time;
    const double theta =
        length > 0.0 ? std::clamp((time - vertices.start_time) / length, 0.0, 1.0) : 1.0;
    const auto at = [&](std::int32_t k) {
        const auto v = static_cast<std::size_t>(k);
        return Vec3((1.0 - theta) * vertices.start[v] + theta * vertices.end[v]);
    };
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto& c = vertices.corners[f];
        Face& face = faces[f];
        face.point = at(c[0]);
        face.edge_u = at(c[1]) - face.point;
        face.edge_v = at(c[2]) - face.point;
        face.normal = face.edge_u.cross(face.edge_v).normalized();
    }
}

Vec3 PlaneWall::barycentric(std::int32_t face, const Vec3& point) const {
    // The point's coordinates (s, t) along the edges from the normal equations of
    // point - a = s e1 + t e2.
    const Face& f = faces[static_cast<std::size_t>(face)];
    const Vec3 ap = point - f.point;
    const double uu = f.edge_u.squaredNorm();
    const double uv = f.edge_u.dot(f.edge_v);
    const double vv = f.edge_v.squaredNorm();
    const double pu = ap.dot(f.edge_u);
    const double pv = ap.dot(f.edge_v);
    const double det = uu * vv - uv * uv;
    const double s = (vv * pu - uv * pv) / det;
    const double t = (uu * pv - uv * pu) / det;
    return {1.0 - s - t, s, t};
}

Vec3 PlaneWall::face_velocity(std::int32_t face, const Vec3& point) const {
    const double length = vertices.end_time - vertices.start_time;
    if (!follows() || !(length > 0.0)) {
        return Vec3::Zero();
    }
    const Vec3 weights = barycentric(face, point);
    Vec3 moving = Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
        const auto v = static_cast<std::size_t>(
            vertices.corners[static_cast<std::size_t>(face)][static_cast<std::size_t>(k)]);
        moving += weights[k] * (vertices.end[v] - vertices.start[v]);
    }
    return moving / length;
}

} // namespace grainload::dem
