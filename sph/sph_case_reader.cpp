#include "sph/sph_case_reader.hpp"

#include "io/case_table.hpp"

#include <cmath>

namespace grainload::sph {

namespace dim = io::dimension;

SphOptions read_sph_options(const io::CaseTable& sph, int dimension, double spacing,
                            const Vec3& gravity) {
    SphOptions options;
    options.dimension = dimension;
    options.gravity = gravity;
    options.particle_spacing = spacing;
    const std::string kernel =
        sph.choice_or("kernel", {"cubic_spline", "quintic_spline", "wendland_c2"}, "cubic_spline");
    options.kernel = kernel_type_from_name(kernel);
    const double ratio = sph.number_or("smoothing_length_ratio", 1.3);
    if (!(ratio >= 0.8 && ratio <= 3.0)) {
        sph.fail("smoothing_length_ratio", "expected h / spacing in [0.8, 3]");
    }
    options.smoothing_length = ratio * spacing;
    options.cfl_safety = sph.number_or("cfl_safety", 0.3);
    if (!(options.cfl_safety > 0.0 && options.cfl_safety <= 1.0)) {
        sph.fail("cfl_safety", "expected a safety factor in (0, 1]");
    }
    options.verlet_skin_factor = sph.number_or("verlet_skin", 0.1);
    if (!(options.verlet_skin_factor >= 0.0 && options.verlet_skin_factor <= 1.0)) {
        sph.fail("verlet_skin", "expected the Verlet skin as a fraction of h in [0, 1]");
    }
    options.kernel_gradient_correction = sph.boolean_or("kernel_gradient_correction", true);
    if (const auto viscosity = sph.optional_table("artificial_viscosity")) {
        options.viscosity.alpha = viscosity->number_or("alpha", 0.0);
        options.viscosity.beta = viscosity->number_or("beta", 0.0);
        if (options.viscosity.alpha < 0.0 || options.viscosity.beta < 0.0) {
            viscosity->fail("", "expected alpha >= 0 and beta >= 0");
        }
    }
    if (const auto stress = sph.optional_table("artificial_stress")) {
        options.artificial_stress.epsilon = stress->number_or("epsilon", 0.0);
        options.artificial_stress.exponent = stress->number_or("exponent", 4.0);
        if (options.artificial_stress.epsilon < 0.0 || options.artificial_stress.exponent <= 0.0) {
            stress->fail("", "expected epsilon >= 0 and exponent > 0");
        }
    }
    if (const auto contact = sph.optional_table("contact")) {
        options.contact.stiffness = contact->positive_quantity("stiffness", dim::kPressure);
        options.contact.exponent = contact->number_or("exponent", 1.0);
        if (!(options.contact.exponent >= 1.0)) {
            contact->fail("exponent", "expected n >= 1");
        }
    }
    return options;
}

namespace {

std::vector<Vec3> wall_points(const io::CaseTable& wall, int dimension, double spacing,
                              int layers) {
    const std::string type = wall.choice("type", {"plane", "box"});
    if (type == "box") {
        const Vec3 lower = wall.vector("min", dim::kLength);
        const Vec3 upper = wall.vector("max", dim::kLength);
        return box_wall_points(lower, upper, spacing, layers, dimension,
                               wall.boolean_or("open_top", true));
    }
    const Vec3 origin = wall.vector("origin", dim::kLength);
    const Vec3 u = wall.vector("edge_u", dim::kLength);
    const Vec3 v = dimension == 3 ? wall.vector("edge_v", dim::kLength) : Vec3::Zero();
    const Vec3 normal = wall.vector("normal", dim::kNone);
    if (!(normal.norm() > 0.0)) {
        wall.fail("normal", "expected a non-zero normal pointing into the material");
    }
    return plane_wall_points(origin, u, v, normal, spacing, layers, dimension);
}

/// `<key>_history` of a wall: [[time, vector], ...] with non-decreasing times, an alternative
/// to the constant `<key>`. The wall starts with the history's value at t = 0.
std::vector<std::pair<double, Vec3>> motion_history(const io::CaseTable& wall,
                                                    const std::string& key, io::Dimension value) {
    const std::string name = key + "_history";
    if (!wall.has(name)) {
        return {};
    }
    if (wall.has(key)) {
        wall.fail(name, "give either " + key + " (constant) or " + name + ", not both");
    }
    auto history = wall.vector_pairs(name, dim::kTime, value);
    for (std::size_t k = 1; k < history.size(); ++k) {
        if (history[k].first < history[k - 1].first) {
            wall.fail(name, "expected non-decreasing times");
        }
    }
    return history;
}

} // namespace

std::vector<RigidWall> read_rigid_walls(const io::CaseTable& sph, ParticleSet& particles,
                                        int dimension, double spacing, double support_radius,
                                        int first_body_id) {
    std::vector<RigidWall> walls;
    for (const auto& table : sph.array_of_tables("wall")) {
        const int default_layers = static_cast<int>(std::ceil(support_radius / spacing));
        const auto layers = table.integer_or("layers", default_layers);
        if (layers < 1 || layers > 10) {
            table.fail("layers", "expected 1 to 10 layers of wall particles");
        }
        const auto points = wall_points(table, dimension, spacing, static_cast<int>(layers));
        const int index = static_cast<int>(walls.size());
        RigidWall wall = add_rigid_wall(particles, table.string("name"), index,
                                        first_body_id + index, points, spacing, 1.0, dimension);
        wall.centre = table.vector_or("centre", dim::kLength, wall.centre);
        wall.velocity = table.vector_or("velocity", dim::kVelocity, Vec3::Zero());
        wall.angular_velocity =
            table.vector_or("angular_velocity", dim::kAngularVelocity, Vec3::Zero());
        wall.velocity_history = motion_history(table, "velocity", dim::kVelocity);
        wall.angular_velocity_history =
            motion_history(table, "angular_velocity", dim::kAngularVelocity);
        if (!wall.velocity_history.empty()) {
            wall.velocity = history_value(wall.velocity_history, 0.0);
        }
        if (!wall.angular_velocity_history.empty()) {
            wall.angular_velocity = history_value(wall.angular_velocity_history, 0.0);
        }
        walls.push_back(std::move(wall));
    }
    return walls;
}

} // namespace grainload::sph
