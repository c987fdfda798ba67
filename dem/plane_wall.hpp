#pragma once
// Rigid walls of a DEM scene: planes, rectangles, boxes as their faces' planes, and triangle
// meshes.

#include "dem/face_grid.hpp"
#include "io/surface_mesh.hpp"
#include "io/types.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace grainload::dem {

/// A rigid wall of flat faces. An unbounded face (`plane`) is the plane through `point` whose
/// unit normal points into the material: a grain whose centre lies closer to it than its radius
/// touches it. A bounded face is the rectangle point + s edge_u + t edge_v (s, t in [0, 1], the
/// edges at right angles) or the triangle point + s edge_u + t edge_v (s, t >= 0, s + t <= 1),
/// a thin plate touched from either side, at its face, edges or corners: the contact's normal
/// runs from the face's point nearest the grain's centre to the centre.
/// A box wall is its five (open top) or six inner faces, unbounded; grains stay inside it,
/// where the planes and the faces agree. A mesh wall is the triangles of a surface mesh (quads
/// split in two), with each triangle's neighbours across its edges and a grid of its faces.
struct PlaneWall {
    enum class Shape : std::uint8_t { plane, rectangle, triangle };
    struct Face {
        Vec3 point = Vec3::Zero();
        Vec3 normal = Vec3::UnitZ();
        Shape shape = Shape::plane;
        Vec3 edge_u = Vec3::Zero();
        Vec3 edge_v = Vec3::Zero();
    };
    std::string name;
    std::vector<Face> faces;
    /// A mesh wall's triangles' neighbours across the edges a-b, b-c and c-a (-1 at a border);
    /// empty for the other walls.
    std::vector<std::array<std::int32_t, 3>> adjacent;
    /// A mesh wall's faces binned for the contact pass, built (and grown) by it.
    FaceGrid grid;
    /// The grains' force on the wall at the last evaluation [N].
    Vec3 force = Vec3::Zero();
    /// The sum of its contacts' normal forces [N]: on a curved wall, whose contacts' forces
    /// cancel in `force`, its pressure times its area.
    double normal_force = 0.0;
    /// The sums of its contacts' normal springs' forces (normal_force less the dashpots') and
    /// of their tangent stiffnesses [N, N/m]: what a servo moving the wall along its normal
    /// meets.
    double elastic_normal_force = 0.0;
    double normal_stiffness = 0.0;
    /// The wall leaves the scene at the end of the step that reaches this time (a gate).
    double remove_at = std::numeric_limits<double>::infinity();
    /// The [[phase]] whose start is remove_at (-1: a time the case states).
    int removal_phase = -1;
    bool removed = false;
    /// A prescribed translation: at `velocity` from `move_start` to `move_end`, at rest
    /// before and after. The faces stay where the case put them; a sphere meets them at its
    /// centre less the wall's `displacement`, and its contact slides at its velocity less the
    /// wall's `current_velocity`, both set by move_to() for the time of the evaluation.
    Vec3 velocity = Vec3::Zero();
    double move_start = 0.0;
    double move_end = std::numeric_limits<double>::infinity();
    Vec3 displacement = Vec3::Zero();
    Vec3 current_velocity = Vec3::Zero();
    /// A wall a controller drives (a servo of the triaxial cell) instead of `velocity`'s
    /// schedule: from `anchor` (its displacement at `anchor_time`) at `velocity`, which the
    /// controller sets after each step.
    bool controlled = false;
    Vec3 anchor = Vec3::Zero();
    double anchor_time = 0.0;

    /// A mesh wall whose vertices move (the mid-surface of a coupled shell, set by the
    /// coupling): their positions at the ends of the interval [start_time, end_time], the faces
    /// linear in time between. A grain touches the plate of thickness 2 half_thickness about
    /// the faces, its load shared among its face's corners by the contact point's barycentric
    /// weights: the virtual work of a force F at y = sum lambda_k x_k + h n (n the face's normal
    /// on the grain's side, the shell's director) is sum lambda_k (F . delta x_k) plus that of
    /// the moment h n x F about the mid-surface.
    struct VertexMotion {
        std::vector<Vec3> start;
        std::vector<Vec3> end;
        double start_time = 0.0;
        double end_time = 0.0;
        /// Each face's three vertices (its point, point + edge_u, point + edge_v).
        std::vector<std::array<std::int32_t, 3>> corners;
        /// The grains' loads at the last evaluation, per vertex: the forces, and the moments of
        /// the forces at the plate's faces about the mid-surface.
        std::vector<Vec3> force;
        std::vector<Vec3> moment;
    };
    VertexMotion vertices;
    double half_thickness = 0.0;

    /// A face a sphere touches (or reaches): its index, overlap and normal as touches() gives.
    struct Touch {
        std::int32_t face = 0;
        double overlap = 0.0;
        Vec3 normal = Vec3::Zero();
    };

    bool mesh() const { return !adjacent.empty(); }
    /// Whether the wall's faces follow moving vertices.
    bool follows() const { return !vertices.start.empty(); }
    /// The vertices' next interval: they start where the last one ended (or at `end` the first
    /// time) and reach `end` at `end_time`.
    void set_interval(const std::vector<Vec3>& end, double start_time, double end_time);
    /// Places the faces of a following wall where its vertices are at `time`.
    void follow(double time);
    /// The velocity of a following wall's face `face` at its point `point` (a point of the
    /// face's plane): the vertices' velocities over the interval, by the point's barycentric
    /// weights; zero for a wall of fixed faces.
    Vec3 face_velocity(std::int32_t face, const Vec3& point) const;
    /// The barycentric weights of `point` (in the plane of triangle `face`) on its corners.
    Vec3 barycentric(std::int32_t face, const Vec3& point) const;
    bool moves() const { return controlled || velocity != Vec3::Zero(); }
    /// Places the wall where its motion has taken it at `time`.
    void move_to(double time) {
        if (controlled) {
            displacement = anchor + velocity * (time - anchor_time);
            current_velocity = velocity;
            return;
        }
        displacement = velocity * std::clamp(time - move_start, 0.0, move_end - move_start);
        current_velocity = time > move_start && time < move_end ? velocity : Vec3::Zero();
    }
    /// Whether a sphere at `centre` of `radius` touches any face of the wall where it is now (a
    /// plate of its thickness about them).
    bool touched_by(const Vec3& centre, double radius) const;
    /// The faces a sphere at `centre` of `radius` touches, in ascending order, into `touched`,
    /// with `centre` in the faces' frame (less the wall's displacement).
    /// Every face of a plane, rectangle or box that it touches. On a mesh, one touch per place:
    /// deepest first, a face is dropped when its nearest point lies on or behind the tangent
    /// plane of a touch already kept, so that the triangles sharing an edge or a corner the
    /// sphere rests on, or lying in the plane of the face it rests on, count once; faces meeting
    /// at a concave fold, each touched at its own point, all count. The grid must reach `radius`.
    void touching_faces(const Vec3& centre, double radius, std::vector<Touch>& touched) const;

    /// The faces of the inside of the box [min, max]; without the face at max along `up` when
    /// `open_top`.
    static std::vector<Face> box_faces(const Vec3& min, const Vec3& max, int up, bool open_top);
    /// Sets the faces, their corners and their neighbours from the triangles and quads of
    /// `mesh` (each quad a-b-c-d as a-b-c and a-c-d); the mesh's faces are of non-zero area.
    void set_mesh(const io::SurfaceMesh& mesh);
    /// Bins the faces for spheres reaching `reach` from their centres (a following wall's
    /// faces over the whole of their interval).
    void index_faces(double reach);
};

/// The point of the triangle a + s e1 + t e2 (s, t >= 0, s + t <= 1) nearest the point a +
/// `ap`, as its offset from a: the Voronoi regions of its vertices, edges and face, tested in
/// turn (Ericson 2005, Real-Time Collision Detection, section 5.1.5).
inline Vec3 nearest_on_triangle(const Vec3& ap, const Vec3& e1, const Vec3& e2) {
    const double d1 = e1.dot(ap);
    const double d2 = e2.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0) {
        return Vec3::Zero();
    }
    const double d3 = d1 - e1.squaredNorm(); // e1 . (p - b)
    const double d4 = d2 - e1.dot(e2);       // e2 . (p - b)
    if (d3 >= 0.0 && d4 <= d3) {
        return e1;
    }
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        return (d1 / (d1 - d3)) * e1;
    }
    const double d5 = d1 - e1.dot(e2);       // e1 . (p - c)
    const double d6 = d2 - e2.squaredNorm(); // e2 . (p - c)
    if (d6 >= 0.0 && d5 <= d6) {
        return e2;
    }
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        return (d2 / (d2 - d6)) * e2;
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
        return e1 + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (e2 - e1);
    }
    const double scale = 1.0 / (va + vb + vc);
    return (vb * scale) * e1 + (vc * scale) * e2;
}

/// Whether a sphere at `centre` of `radius` touches `face`; then its overlap and the contact's
/// unit normal, from the face to the centre. Inline: the contact pass asks it for every sphere
/// and face near it at every step.
inline bool touches(const PlaneWall::Face& face, const Vec3& centre, double radius, double& overlap,
                    Vec3& normal) {
    const Vec3 offset = centre - face.point;
    if (face.shape == PlaneWall::Shape::plane) {
        const double gap = offset.dot(face.normal);
        overlap = radius - gap;
        normal = face.normal;
        return gap < radius;
    }
    Vec3 away;
    if (face.shape == PlaneWall::Shape::rectangle) {
        const double s = std::clamp(offset.dot(face.edge_u) / face.edge_u.squaredNorm(), 0.0, 1.0);
        const double t = std::clamp(offset.dot(face.edge_v) / face.edge_v.squaredNorm(), 0.0, 1.0);
        away = offset - s * face.edge_u - t * face.edge_v;
    } else {
        away = offset - nearest_on_triangle(offset, face.edge_u, face.edge_v);
    }
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
