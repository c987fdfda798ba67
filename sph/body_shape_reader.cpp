#include "sph/body_shape_reader.hpp"

#include "io/case_table.hpp"
#include "io/surface_mesh_reader.hpp"
#include "materials/material_case_reader.hpp"
#include "sph/closed_mesh_fill.hpp"
#include "sph/keyword_body_reader.hpp"

#include <string>

namespace grainload::sph {

namespace {

namespace dim = io::dimension;
using Type = ShapeSettings::Type;

/// type = "mesh": the surface of the table's `file` (see io::read_surface_mesh), refused
/// unless closed and in a 3D case.
void read_mesh_shape(const io::CaseTable& shape, int dimension, ShapeSettings& settings) {
    if (dimension != 3) {
        shape.fail("type", "a mesh body needs a 3D case (dimension = 3); in plane strain use "
                           "box, cylinder or cone");
    }
    settings.mesh = io::read_surface_mesh(shape);
    if (settings.mesh.triangles.empty() && settings.mesh.quads.empty()) {
        shape.fail("file", "the mesh has no triangles or quadrangles to fill");
    }
    const EdgeUse edges = count_edge_use(settings.mesh);
    if (edges.boundary > 0 || edges.non_manifold > 0) {
        shape.fail("file",
                   "a mesh body needs a closed (watertight) surface: " +
                       std::to_string(edges.boundary) + " boundary edges (in one face only) and " +
                       std::to_string(edges.non_manifold) + " edges in more than two faces");
    }
}

/// A 3D cylinder (type "cylinder") or a cone or frustum (type "cone") of a shape table.
void read_cone_shape(const io::CaseTable& shape, int dimension, ShapeSettings& settings) {
    settings.base = shape.vector("base", dim::kLength);
    settings.axis = shape.vector("axis", dim::kNone);
    Vec3 in_plane = settings.axis;
    if (dimension == 2) {
        in_plane.z() = 0.0;
    }
    if (!(in_plane.norm() > 0.0)) {
        shape.fail("axis", "expected a non-zero axis direction");
    }
    settings.height = shape.positive_quantity("height", dim::kLength);
    if (settings.type == Type::cylinder) {
        settings.base_radius = settings.top_radius =
            shape.positive_quantity("radius", dim::kLength);
        settings.radius = settings.base_radius;
        return;
    }
    settings.base_radius = shape.positive_quantity("base_radius", dim::kLength);
    settings.top_radius =
        shape.quantity_or("top_radius", dim::kLength, io::default_value(kShapeKeys, "top_radius"));
    if (settings.top_radius < 0.0) {
        shape.fail("top_radius", "expected a radius >= 0 (0: a full cone)");
    }
}

/// lattice = "jittered": each point moved within its cell by the shape's jitter and seed.
void read_jitter(const io::CaseTable& shape, ShapeSettings& settings) {
    settings.jittered = shape.choice_or("lattice", {"regular", "jittered"},
                                        io::default_text(kShapeKeys, "lattice")) == "jittered";
    if (!settings.jittered) {
        return;
    }
    settings.jitter = shape.number_or("jitter", io::default_value(kShapeKeys, "jitter"));
    if (!(settings.jitter >= 0.0 && settings.jitter < 0.5)) {
        shape.fail("jitter", "expected a fraction of the spacing in [0, 0.5)");
    }
    settings.seed = static_cast<std::uint64_t>(
        shape.integer_or("seed", static_cast<std::int64_t>(io::default_value(kShapeKeys, "seed"))));
}

/// [[sph.body.shape.cut]] tables (point, normal, offset): each keeps the points on the side its
/// normal points to, at least `offset` from the plane, so a box cut by planes fills a convex
/// polyhedron (the load of a hopper or wagon above its slope sheets).
void read_cuts(const io::CaseTable& shape, int dimension, ShapeSettings& settings) {
    for (const io::CaseTable& table : shape.array_of_tables("cut")) {
        ShapeSettings::Cut cut;
        cut.point = table.vector("point", dim::kLength);
        cut.normal = table.vector("normal", dim::kNone);
        if (dimension == 2) {
            cut.normal.z() = 0.0;
        }
        if (!(cut.normal.norm() > 0.0)) {
            table.fail("normal", "expected a non-zero normal (towards the particles kept)");
        }
        cut.normal.normalize();
        cut.offset =
            table.quantity_or("offset", dim::kLength, io::default_value(kCutKeys, "offset"));
        cut.places = io::KeyPlaces(table, {"normal"});
        settings.cuts.push_back(std::move(cut));
    }
}

/// (x - point) . n >= offset for each cut.
void cut_points(const ShapeSettings& shape, std::vector<Vec3>& points) {
    for (const ShapeSettings::Cut& cut : shape.cuts) {
        std::erase_if(points,
                      [&](const Vec3& x) { return (x - cut.point).dot(cut.normal) < cut.offset; });
        if (points.empty()) {
            cut.places.fail("normal", "the cut removes every particle of the shape: expected the "
                                      "normal to point towards the particles kept");
        }
    }
}

std::vector<Vec3> fill_mesh(const ShapeSettings& shape, double spacing) {
    try {
        return fill_closed_mesh(shape.mesh, spacing);
    } catch (const std::runtime_error& error) {
        shape.places.fail("file", error.what());
    }
}

} // namespace

ShapeSettings read_shape(const io::CaseTable& shape, double spacing, int dimension,
                         double density) {
    ShapeSettings settings;
    const std::string type = shape.choice("type", {"box", "cylinder", "cone", "mesh", "lsdyna"});
    settings.places = io::KeyPlaces(shape, {"type", "file"});
    if (type == "lsdyna") {
        settings.type = Type::lsdyna;
        settings.deck_points = read_keyword_particles(shape, spacing, dimension, density);
    } else if (type == "mesh") {
        settings.type = Type::mesh;
        read_mesh_shape(shape, dimension, settings);
    } else if (type == "box") {
        settings.min = shape.vector("min", dim::kLength);
        settings.max = shape.vector("max", dim::kLength);
        for (int axis = 0; axis < dimension; ++axis) {
            if (!(settings.max[axis] > settings.min[axis])) {
                shape.fail("max", "expected max > min in every direction");
            }
        }
    } else if (type == "cylinder" && dimension == 2) {
        settings.type = Type::disc;
        settings.centre = shape.vector("centre", dim::kLength);
        settings.radius = shape.positive_quantity("radius", dim::kLength);
    } else {
        settings.type = type == "cylinder" ? Type::cylinder : Type::cone;
        read_cone_shape(shape, dimension, settings);
    }
    read_cuts(shape, dimension, settings);
    read_jitter(shape, settings);
    return settings;
}

std::vector<Vec3> fill_shape(const ShapeSettings& shape, double spacing, int dimension,
                             std::vector<RoundedSize>* rounded) {
    std::vector<Vec3> points;
    switch (shape.type) {
    case Type::lsdyna:
        points = shape.deck_points;
        break;
    case Type::mesh:
        points = fill_mesh(shape, spacing);
        break;
    case Type::box:
        points = fill_box(shape.min, shape.max, spacing, dimension);
        break;
    case Type::disc:
        points = fill_disc(shape.centre, shape.radius, spacing, dimension);
        break;
    case Type::cylinder:
    case Type::cone:
        points = fill_cone(shape.base, shape.axis, shape.base_radius, shape.top_radius,
                           shape.height, spacing, dimension);
        break;
    }
    if (points.empty()) {
        shape.places.fail("type", "the shape holds no lattice cell centre: make it larger than "
                                  "the spacing");
    }
    cut_points(shape, points);
    if (rounded != nullptr) {
        if (const auto drawn = drawn_bounds(shape, dimension)) {
            *rounded = lattice_rounding(*drawn, points, spacing, dimension);
        }
    }
    if (shape.jittered) {
        jitter_points(points, spacing, shape.jitter, shape.seed, dimension);
    }
    return points;
}

BodySettings read_body_settings(const io::CaseTable& body,
                                const materials::MaterialLibrary& materials, int dimension) {
    BodySettings settings;
    settings.name = body.string("name");
    settings.material = materials::read_material_index(materials, body, "material");
    settings.spacing = body.positive_quantity("spacing", dim::kLength);
    settings.velocity =
        body.vector_or("velocity", dim::kVelocity, io::default_vector(kBodyKeys, "velocity"));
    settings.shape = read_shape(body.table("shape"), settings.spacing, dimension,
                                materials[settings.material].density());
    return settings;
}

std::vector<Vec3> generate_body_points(const io::CaseTable& shape, double spacing, int dimension,
                                       double density, std::vector<RoundedSize>* rounded) {
    return fill_shape(read_shape(shape, spacing, dimension, density), spacing, dimension, rounded);
}

std::optional<std::pair<Vec3, Vec3>> drawn_bounds(const ShapeSettings& shape, int dimension) {
    if (!shape.cuts.empty() || shape.type == Type::mesh || shape.type == Type::lsdyna) {
        return std::nullopt;
    }
    if (shape.type == Type::box) {
        return std::pair{shape.min, shape.max};
    }
    if (shape.type == Type::disc) {
        const Vec3 reach = Vec3::Constant(shape.radius);
        return std::pair{Vec3(shape.centre - reach), Vec3(shape.centre + reach)};
    }
    // A cylinder or cone: the bounding box of its end discs (segments in plane strain). A disc
    // of radius r normal to the unit axis a reaches r sqrt(1 - a_i^2) along axis i.
    Vec3 axis = shape.axis;
    if (dimension == 2) {
        axis.z() = 0.0;
    }
    axis.normalize();
    const Vec3 top = shape.base + shape.height * axis;
    Vec3 across;
    for (int i = 0; i < 3; ++i) {
        across[i] = std::sqrt(std::max(0.0, 1.0 - axis[i] * axis[i]));
    }
    const Vec3 lower =
        (shape.base - shape.base_radius * across).cwiseMin(top - shape.top_radius * across);
    const Vec3 upper =
        (shape.base + shape.base_radius * across).cwiseMax(top + shape.top_radius * across);
    return std::pair{lower, upper};
}

} // namespace grainload::sph
