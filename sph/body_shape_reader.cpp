#include "sph/body_shape_reader.hpp"

#include "io/case_table.hpp"
#include "io/surface_mesh_reader.hpp"
#include "sph/closed_mesh_fill.hpp"
#include "sph/keyword_body_reader.hpp"

#include <cstdint>
#include <string>

namespace grainload::sph {

namespace {

/// [sph.body.shape] type = "mesh": the points filling the mesh of the table's `file`
/// (see io::read_surface_mesh), refused unless closed and in a 3D case.
std::vector<Vec3> fill_mesh_shape(const io::CaseTable& shape, double spacing, int dimension);

std::vector<Vec3> fill_mesh_shape(const io::CaseTable& shape, double spacing, int dimension) {
    if (dimension != 3) {
        shape.fail("type", "a mesh body needs a 3D case (dimension = 3); in plane strain use "
                           "box, cylinder or cone");
    }
    const io::SurfaceMesh mesh = io::read_surface_mesh(shape);
    if (mesh.triangles.empty() && mesh.quads.empty()) {
        shape.fail("file", "the mesh has no triangles or quadrangles to fill");
    }
    const EdgeUse edges = count_edge_use(mesh);
    if (edges.boundary > 0 || edges.non_manifold > 0) {
        shape.fail("file",
                   "a mesh body needs a closed (watertight) surface: " +
                       std::to_string(edges.boundary) + " boundary edges (in one face only) and " +
                       std::to_string(edges.non_manifold) + " edges in more than two faces");
    }
    try {
        return fill_closed_mesh(mesh, spacing);
    } catch (const std::runtime_error& error) {
        shape.fail("file", error.what());
    }
}

/// A 3D cylinder (type "cylinder") or a cone or frustum (type "cone") of a shape table.
std::vector<Vec3> fill_cone_shape(const io::CaseTable& shape, const std::string& type,
                                  double spacing, int dimension) {
    namespace dim = io::dimension;
    const Vec3 base = shape.vector("base", dim::kLength);
    const Vec3 axis = shape.vector("axis", dim::kNone);
    Vec3 in_plane = axis;
    if (dimension == 2) {
        in_plane.z() = 0.0;
    }
    if (!(in_plane.norm() > 0.0)) {
        shape.fail("axis", "expected a non-zero axis direction");
    }
    const double height = shape.positive_quantity("height", dim::kLength);
    double base_radius = 0.0;
    double top_radius = 0.0;
    if (type == "cylinder") {
        base_radius = top_radius = shape.positive_quantity("radius", dim::kLength);
    } else {
        base_radius = shape.positive_quantity("base_radius", dim::kLength);
        top_radius = shape.quantity_or("top_radius", dim::kLength,
                                       io::default_value(kShapeKeys, "top_radius"));
        if (top_radius < 0.0) {
            shape.fail("top_radius", "expected a radius >= 0 (0: a full cone)");
        }
    }
    return fill_cone(base, axis, base_radius, top_radius, height, spacing, dimension);
}

/// lattice = "jittered": each point moved within its cell by the shape's jitter and seed.
void jitter_shape(const io::CaseTable& shape, std::vector<Vec3>& points, double spacing,
                  int dimension) {
    if (shape.choice_or("lattice", {"regular", "jittered"},
                        io::default_text(kShapeKeys, "lattice")) != "jittered") {
        return;
    }
    const double fraction = shape.number_or("jitter", io::default_value(kShapeKeys, "jitter"));
    if (!(fraction >= 0.0 && fraction < 0.5)) {
        shape.fail("jitter", "expected a fraction of the spacing in [0, 0.5)");
    }
    const auto seed =
        shape.integer_or("seed", static_cast<std::int64_t>(io::default_value(kShapeKeys, "seed")));
    jitter_points(points, spacing, fraction, static_cast<std::uint64_t>(seed), dimension);
}

} // namespace

void cut_points(const io::CaseTable& shape, std::vector<Vec3>& points, int dimension) {
    namespace dim = io::dimension;
    for (const io::CaseTable& cut : shape.array_of_tables("cut")) {
        const Vec3 point = cut.vector("point", dim::kLength);
        Vec3 normal = cut.vector("normal", dim::kNone);
        if (dimension == 2) {
            normal.z() = 0.0;
        }
        if (!(normal.norm() > 0.0)) {
            cut.fail("normal", "expected a non-zero normal (towards the particles kept)");
        }
        normal.normalize();
        const double offset =
            cut.quantity_or("offset", dim::kLength, io::default_value(kCutKeys, "offset"));
        std::erase_if(points, [&](const Vec3& x) { return (x - point).dot(normal) < offset; });
        if (points.empty()) {
            cut.fail("normal", "the cut removes every particle of the shape: expected the "
                               "normal to point towards the particles kept");
        }
    }
}

std::vector<Vec3> generate_body_points(const io::CaseTable& shape, double spacing, int dimension,
                                       double density, std::vector<RoundedSize>* rounded) {
    namespace dim = io::dimension;
    const std::string type = shape.choice("type", {"box", "cylinder", "cone", "mesh", "lsdyna"});
    std::vector<Vec3> points;
    if (type == "lsdyna") {
        points = read_keyword_particles(shape, spacing, dimension, density);
    } else if (type == "mesh") {
        points = fill_mesh_shape(shape, spacing, dimension);
    } else if (type == "box") {
        const Vec3 min = shape.vector("min", dim::kLength);
        const Vec3 max = shape.vector("max", dim::kLength);
        for (int axis = 0; axis < dimension; ++axis) {
            if (!(max[axis] > min[axis])) {
                shape.fail("max", "expected max > min in every direction");
            }
        }
        points = fill_box(min, max, spacing, dimension);
    } else if (type == "cylinder" && dimension == 2) {
        points = fill_disc(shape.vector("centre", dim::kLength),
                           shape.positive_quantity("radius", dim::kLength), spacing, dimension);
    } else {
        points = fill_cone_shape(shape, type, spacing, dimension);
    }
    if (points.empty()) {
        shape.fail("type", "the shape holds no lattice cell centre: make it larger than the "
                           "spacing");
    }
    cut_points(shape, points, dimension);
    if (rounded != nullptr) {
        if (const auto drawn = drawn_bounds(shape, dimension)) {
            *rounded = lattice_rounding(*drawn, points, spacing, dimension);
        }
    }
    jitter_shape(shape, points, spacing, dimension);
    return points;
}

std::optional<std::pair<Vec3, Vec3>> drawn_bounds(const io::CaseTable& shape, int dimension) {
    namespace dim = io::dimension;
    const std::string type = shape.string("type");
    if (shape.has("cut") || (type != "box" && type != "cylinder" && type != "cone")) {
        return std::nullopt;
    }
    if (type == "box") {
        return std::pair{shape.vector("min", dim::kLength), shape.vector("max", dim::kLength)};
    }
    if (type == "cylinder" && dimension == 2) {
        const Vec3 centre = shape.vector("centre", dim::kLength);
        const Vec3 reach = Vec3::Constant(shape.quantity("radius", dim::kLength));
        return std::pair{Vec3(centre - reach), Vec3(centre + reach)};
    }
    // A cylinder or cone: the bounding box of its end discs (segments in plane strain). A disc
    // of radius r normal to the unit axis a reaches r sqrt(1 - a_i^2) along axis i.
    Vec3 axis = shape.vector("axis", dim::kNone);
    if (dimension == 2) {
        axis.z() = 0.0;
    }
    axis.normalize();
    const Vec3 base = shape.vector("base", dim::kLength);
    const Vec3 top = base + shape.quantity("height", dim::kLength) * axis;
    const double base_radius = type == "cylinder" ? shape.quantity("radius", dim::kLength)
                                                  : shape.quantity("base_radius", dim::kLength);
    const double top_radius = type == "cylinder"
                                  ? base_radius
                                  : shape.quantity_or("top_radius", dim::kLength,
                                                      io::default_value(kShapeKeys, "top_radius"));
    Vec3 across;
    for (int i = 0; i < 3; ++i) {
        across[i] = std::sqrt(std::max(0.0, 1.0 - axis[i] * axis[i]));
    }
    const Vec3 lower = (base - base_radius * across).cwiseMin(top - top_radius * across);
    const Vec3 upper = (base + base_radius * across).cwiseMax(top + top_radius * across);
    return std::pair{lower, upper};
}

} // namespace grainload::sph
