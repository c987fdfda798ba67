#pragma once
// Rigid walls of a DEM scene: planes, rectangles, and boxes as their faces' planes.

#include "io/types.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace grainload::dem {

/// A rigid wall of flat faces. An unbounded face is the plane through `point` whose unit normal
/// points into the material: a grain whose centre lies closer to it than its radius touches
/// it. A bounded face is the rectangle point + s edge_u + t edge_v (s, t in [0, 1], the edges
/// at right angles), a thin plate touched from either side, at its face, edges or corners: the
/// contact's normal runs from the rectangle's point nearest the grain's centre to the centre.
/// A box wall is its five (open top) or six inner faces, unbounded; grains stay inside it,
/// where the planes and the faces agree.
struct PlaneWall {
    struct Face {
        Vec3 point = Vec3::Zero();
        Vec3 normal = Vec3::UnitZ();
        bool bounded = false;
        Vec3 edge_u = Vec3::Zero();
        Vec3 edge_v = Vec3::Zero();
    };
    std::string name;
    std::vector<Face> faces;
    /// The grains' force on the wall at the last evaluation [N].
    Vec3 force = Vec3::Zero();
    /// The wall leaves the scene at the end of the step that reaches this time (a gate).
    double remove_at = std::numeric_limits<double>::infinity();
    bool removed = false;

    /// The faces of the inside of the box [min, max]; without the face at max along `up` when
    /// `open_top`.
    static std::vector<Face> box_faces(const Vec3& min, const Vec3& max, int up, bool open_top);
};

/// Whether a sphere at `centre` of `radius` touches `face`; then its overlap and the contact's
/// unit normal, from the face to the centre. Inline: the contact pass asks it for every sphere
/// and face at every step.
inline bool touches(const PlaneWall::Face& face, const Vec3& centre, double radius, double& overlap,
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
    // A centre on the plate itself (a grain sliced in two): the face's own normal decides.
    normal = distance > 0.0 ? Vec3(away / distance) : face.normal;
    return true;
}

} // namespace grainload::dem
