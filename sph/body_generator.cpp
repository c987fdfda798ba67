#include "sph/body_generator.hpp"

#include "io/case_table.hpp"

#include <cmath>

namespace grainload::sph {

std::vector<Vec3> fill_box(const Vec3& min, const Vec3& max, double spacing, int dimension) {
    // Each particle represents a cell of volume spacing^dimension, so the cells tile the box
    // exactly when its edges are multiples of the spacing; otherwise the count rounds.
    Eigen::Vector3i count = Eigen::Vector3i::Ones();
    for (int axis = 0; axis < dimension; ++axis) {
        count[axis] = std::max(1, static_cast<int>(std::lround((max[axis] - min[axis]) / spacing)));
    }
    std::vector<Vec3> points;
    points.reserve(static_cast<std::size_t>(count.prod()));
    for (int k = 0; k < count.z(); ++k) {
        for (int j = 0; j < count.y(); ++j) {
            for (int i = 0; i < count.x(); ++i) {
                Vec3 p = min + spacing * Vec3(i + 0.5, j + 0.5, k + 0.5);
                if (dimension == 2) {
                    p.z() = 0.0;
                }
                points.push_back(p);
            }
        }
    }
    return points;
}

std::vector<Vec3> generate_body_points(const io::CaseTable& shape, double spacing, int dimension) {
    namespace dim = io::dimension;
    const std::string type = shape.choice("type", {"box"});
    const Vec3 min = shape.vector("min", dim::kLength);
    const Vec3 max = shape.vector("max", dim::kLength);
    for (int axis = 0; axis < dimension; ++axis) {
        if (!(max[axis] > min[axis])) {
            shape.fail("max", "expected max > min in every direction");
        }
    }
    return fill_box(min, max, spacing, dimension);
}

} // namespace grainload::sph
