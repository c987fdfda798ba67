#include "dem/plane_wall.hpp"

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

} // namespace grainload::dem
