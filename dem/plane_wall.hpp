#pragma once
// Rigid walls of a DEM scene: planes, and boxes as their faces' planes.

#include "io/types.hpp"

#include <string>
#include <vector>

namespace grainload::dem {

/// A rigid wall of flat faces, each an unbounded plane through `point` whose unit normal points
/// into the material: a grain whose centre lies closer to a face than its radius touches it.
/// A box wall is its five (open top) or six inner faces; grains stay inside it, where the
/// unbounded planes and the faces agree.
struct PlaneWall {
    struct Face {
        Vec3 point = Vec3::Zero();
        Vec3 normal = Vec3::UnitZ();
    };
    std::string name;
    std::vector<Face> faces;
    /// The grains' force on the wall at the last evaluation [N].
    Vec3 force = Vec3::Zero();

    /// The faces of the inside of the box [min, max]; without the face at max along `up` when
    /// `open_top`.
    static std::vector<Face> box_faces(const Vec3& min, const Vec3& max, int up, bool open_top);
};

} // namespace grainload::dem
