#pragma once
// Rigid walls of a DEM scene: planes, rectangles, and boxes as their faces' planes.

#include "io/types.hpp"

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
/// unit normal, from the face to the centre.
bool touches(const PlaneWall::Face& face, const Vec3& centre, double radius, double& overlap,
             Vec3& normal);

} // namespace grainload::dem
