#include "dem/plane_wall.hpp"

#include <algorithm>

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

bool touches(const PlaneWall::Face& face, const Vec3& centre, double radius, double& overlap,
             Vec3& normal) {
    const Vec3 offset = centre - face.point;
    if (!face.bounded) {
        const double gap = offset.dot(face.normal);
        overlap = radius - gap;
        normal = face.normal;
        return gap < radius;
    }
    const double s = std::clamp(offset.dot(face.edge_u) / face.edge_u.squaredNorm(), 0.0, 1.0);
    const double t = std::clamp(offset.dot(face.edge_v) / face.edge_v.squaredNorm(), 0.0, 1.0);
    const Vec3 away = offset - s * face.edge_u - t * face.edge_v;
    const double distance = away.norm();
    if (distance >= radius) {
        return false;
    }
    overlap = radius - distance;
    // A centre on the plate itself (a grain sliced in two) is pushed to the side it came from
    // no longer: the face's own normal decides.
    normal = distance > 0.0 ? Vec3(away / distance) : face.normal;
    return true;
}

} // namespace grainload::dem
