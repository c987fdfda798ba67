#include "dem/dem_body_reader.hpp"

#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "materials/material_case_reader.hpp"
#include "materials/material_library.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace grainload::dem {

namespace dim = io::dimension;

namespace {

/// sphere_centres: three numbers per sphere, 2 to 16 spheres; sphere_radii, one per centre; no
/// two spheres overlapping (touching at most: overlapping spheres would count their common
/// volume twice).
void read_sphere_centres(const io::CaseTable& table, BodySettings& body) {
    for (const char* key : {"spheres", "sphere_distance"}) {
        if (table.has(key)) {
            table.fail(key, "sphere_centres places the clump's spheres: expected either "
                            "sphere_centres or spheres and sphere_distance");
        }
    }
    const std::vector<double> values = table.quantity_list("sphere_centres", dim::kNone);
    if (values.size() % 3 != 0 || values.size() < 6 || values.size() > 48) {
        table.fail("sphere_centres", "expected x y z of 2 to 16 sphere centres, three numbers "
                                     "each; got " +
                                         std::to_string(values.size()) + " numbers");
    }
    for (std::size_t k = 0; k < values.size(); k += 3) {
        body.sphere_centres.emplace_back(values[k], values[k + 1], values[k + 2]);
    }
    body.spheres = static_cast<int>(body.sphere_centres.size());
    if (table.has("sphere_radii")) {
        body.sphere_radii = table.quantity_list("sphere_radii", dim::kNone);
        if (body.sphere_radii.size() != body.sphere_centres.size()) {
            table.fail("sphere_radii", "expected one radius per sphere centre (" +
                                           std::to_string(body.spheres) + "), got " +
                                           std::to_string(body.sphere_radii.size()));
        }
        for (const double r : body.sphere_radii) {
            if (!(r >= 0.1 && r <= 10.0)) {
                table.fail("sphere_radii", "expected radii in [0.1, 10] of the grain's radius");
            }
        }
    }
    // Touching spheres are their radii's sum apart; a centre typed to a few digits may land a
    // hair inside.
    constexpr double kTouching = 1.0 - 1e-9;
    for (std::size_t a = 0; a < body.sphere_centres.size(); ++a) {
        for (std::size_t b = a + 1; b < body.sphere_centres.size(); ++b) {
            const double touch = body.sphere_radius(a) + body.sphere_radius(b);
            if (!((body.sphere_centres[a] - body.sphere_centres[b]).norm() >= kTouching * touch)) {
                table.fail("sphere_centres",
                           "spheres " + std::to_string(a + 1) + " and " + std::to_string(b + 1) +
                               " overlap: expected centres at least their radii's sum apart "
                               "(overlapping spheres would count their common volume twice)");
            }
        }
    }
}

/// spheres and sphere_distance: a clump of equal spheres on one axis.
void read_axial_clump(const io::CaseTable& table, BodySettings& body) {
    const std::int64_t spheres = table.integer_or(
        "spheres", static_cast<std::int64_t>(io::default_value(kDemBodyKeys, "spheres")));
    if (spheres < 1 || spheres > 16) {
        table.fail("spheres", "expected an integer in [1, 16]");
    }
    body.spheres = static_cast<int>(spheres);
    body.sphere_distance =
        table.number_or("sphere_distance", io::default_value(kDemBodyKeys, "sphere_distance"));
    // The clump's mass is its spheres' sum: overlapping spheres would count their lens twice.
    if (!(body.sphere_distance >= 1.0 && body.sphere_distance <= 10.0)) {
        table.fail("sphere_distance", "expected a number in [1, 10]: the spheres of a clump "
                                      "touch or stand apart (overlapping ones would count "
                                      "their common volume twice)");
    }
}

void read_clump(const io::CaseTable& table, BodySettings& body) {
    if (table.has("sphere_centres")) {
        read_sphere_centres(table, body);
    } else if (table.has("sphere_radii")) {
        table.fail("sphere_radii", "sphere_radii sizes the spheres of sphere_centres: expected "
                                   "sphere_centres beside it");
    } else {
        read_axial_clump(table, body);
    }
    body.axis = table.vector_or("axis", dim::kNone, io::default_vector(kDemBodyKeys, "axis"));
    if (!(body.axis.norm() > 0.0)) {
        table.fail("axis", "expected a non-zero vector");
    }
}

void read_placement(const io::CaseTable& table, BodySettings& body) {
    if (table.has("centre")) {
        for (const char* key : {"min", "max", "count"}) {
            if (table.has(key)) {
                table.fail(key, "a body with a centre is one grain there: expected no " +
                                    std::string(key));
            }
        }
        if (body.radius_min != body.radius_max) {
            table.fail("centre", "a body with a centre is one grain: expected its radius, not "
                                 "radius_min and radius_max");
        }
        body.centre = table.vector("centre", dim::kLength);
        body.where = table.where("centre");
        return;
    }
    if (!table.has("min") && !table.has("max") && !table.has("count")) {
        // No grains at the start: a [[dem.source]] must rain them in (checked once the
        // sources are read).
        body.count = 0;
        body.where = table.where("name");
        return;
    }
    body.min = table.vector("min", dim::kLength);
    body.max = table.vector("max", dim::kLength);
    body.count = table.integer("count");
    body.where = table.where("count");
    if (body.count < 1) {
        table.fail("count", "expected at least one grain");
    }
    // A grain of the largest radius, turned any way, reaches r_max reach() from its centre.
    const double extent = body.radius_max * body.reach();
    for (int a = 0; a < 3; ++a) {
        if (!(body.max[a] - body.min[a] >= 2.0 * extent)) {
            table.fail("max", body.sphere_centres.empty()
                                  ? "the box must hold a grain of the largest radius turned any "
                                    "way: expected max - min >= 2 radius_max (1 + (spheres - 1) "
                                    "sphere_distance) on every axis"
                                  : "the box must hold a grain of the largest radius turned any "
                                    "way: expected max - min >= 2 radius_max (the farthest "
                                    "sphere's reach from the clump's centre of mass, in radii) "
                                    "on every axis");
        }
    }
}

} // namespace

double BodySettings::reach() const {
    if (sphere_centres.empty()) {
        return 1.0 + (spheres - 1) * sphere_distance;
    }
    // The centre of mass: the centres weighted by their spheres' volumes.
    Vec3 centroid = Vec3::Zero();
    for (std::size_t k = 0; k < sphere_centres.size(); ++k) {
        centroid += std::pow(sphere_radius(k), 3) * sphere_centres[k];
    }
    centroid /= volume_ratio();
    double farthest = 0.0;
    for (std::size_t k = 0; k < sphere_centres.size(); ++k) {
        farthest = std::max(farthest, (sphere_centres[k] - centroid).norm() + sphere_radius(k));
    }
    return farthest;
}

double BodySettings::largest_sphere() const {
    return sphere_radii.empty() ? 1.0 : *std::max_element(sphere_radii.begin(), sphere_radii.end());
}

double BodySettings::smallest_sphere() const {
    return sphere_radii.empty() ? 1.0 : *std::min_element(sphere_radii.begin(), sphere_radii.end());
}

double BodySettings::volume_ratio() const {
    if (sphere_radii.empty()) {
        return static_cast<double>(spheres);
    }
    double sum = 0.0;
    for (const double r : sphere_radii) {
        sum += r * r * r;
    }
    return sum;
}

BodySettings read_dem_body(const io::CaseTable& table,
                           const materials::MaterialLibrary& materials) {
    BodySettings body;
    body.name = table.string("name");
    body.material = materials::read_material_index(materials, table, "material");
    if (materials[body.material].model() != "linear_elastic") {
        table.fail("material", "a grain's material is the solid grain's: expected a "
                               "linear_elastic [[material]], got " +
                                   std::string(materials[body.material].model()));
    }
    if (table.has("radius")) {
        if (table.has("radius_min") || table.has("radius_max")) {
            table.fail("radius", "expected either radius or radius_min and radius_max");
        }
        body.radius_min = body.radius_max = table.positive_quantity("radius", dim::kLength);
    } else {
        body.radius_min = table.positive_quantity("radius_min", dim::kLength);
        body.radius_max = table.positive_quantity("radius_max", dim::kLength);
        if (body.radius_max < body.radius_min) {
            table.fail("radius_max", "expected radius_max >= radius_min");
        }
    }
    read_clump(table, body);
    read_placement(table, body);
    body.velocity =
        table.vector_or("velocity", dim::kVelocity, io::default_vector(kDemBodyKeys, "velocity"));
    body.angular_velocity = table.vector_or("angular_velocity", dim::kAngularVelocity,
                                            io::default_vector(kDemBodyKeys, "angular_velocity"));
    body.rotation =
        table.boolean_or("rotation", io::default_value(kDemBodyKeys, "rotation") != 0.0);
    const std::int64_t seed = table.integer_or(
        "seed", static_cast<std::int64_t>(io::default_value(kDemBodyKeys, "seed")));
    if (seed < 0) {
        table.fail("seed", "expected an integer >= 0");
    }
    body.seed = static_cast<std::uint64_t>(seed);
    return body;
}

} // namespace grainload::dem
