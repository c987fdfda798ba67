#include "sph/particle_estimate.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace grainload::sph {

std::string estimate_text(double value) {
    std::ostringstream out;
    out.precision(3);
    out << value;
    return out.str();
}

ParticleCount count_box(const Vec3& lower, const Vec3& upper, double spacing, int dimension) {
    ParticleCount count;
    count.particles = 1.0;
    std::string edges;
    for (int a = 0; a < dimension; ++a) {
        const double edge = std::abs(upper[a] - lower[a]);
        count.particles *= std::max(1.0, std::round(edge / spacing));
        edges += (a == 0 ? "" : " x ") + estimate_text(edge);
    }
    count.basis = edges + " m box / spacing^" + std::to_string(dimension);
    return count;
}

namespace {

/// Cylinder and cone: the frustum's volume (3D) or its axial section (2D); a disc's area.
ParticleCount round_body(const ShapeSettings& shape, double spacing, int dimension) {
    ParticleCount count;
    if (shape.type == ShapeSettings::Type::disc) {
        const double r = shape.radius;
        count.particles = std::numbers::pi * r * r / (spacing * spacing);
        count.basis = "disc of radius " + estimate_text(r) + " m / spacing^2";
        return count;
    }
    const double r0 = shape.base_radius;
    const double r1 = shape.top_radius;
    const double measure =
        dimension == 3 ? std::numbers::pi * shape.height * (r0 * r0 + r0 * r1 + r1 * r1) / 3.0
                       : shape.height * (r0 + r1);
    count.particles = measure / std::pow(spacing, dimension);
    const char* type = shape.type == ShapeSettings::Type::cylinder ? "cylinder" : "cone";
    count.basis = std::string(type) + " of height " + estimate_text(shape.height) +
                  " m / spacing^" + std::to_string(dimension);
    return count;
}

} // namespace

/// Volume enclosed by a closed surface (divergence theorem over its triangles, quadrangles
/// split along a diagonal): sum of a . (b x c) / 6.
double enclosed_volume(const io::SurfaceMesh& mesh) {
    double six_volume = 0.0;
    for (const auto& t : mesh.triangles) {
        six_volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
    }
    for (const auto& q : mesh.quads) {
        const Vec3& a = mesh.vertices[q[0]];
        six_volume += a.dot(mesh.vertices[q[1]].cross(mesh.vertices[q[2]]));
        six_volume += a.dot(mesh.vertices[q[2]].cross(mesh.vertices[q[3]]));
    }
    return std::abs(six_volume) / 6.0;
}

/// Surface area of a mesh (3D) or length of its polyline (2D).
double surface_measure(const io::SurfaceMesh& mesh, int dimension) {
    double measure = 0.0;
    if (dimension == 2) {
        for (const auto& s : mesh.segments) {
            measure += (mesh.vertices[s[1]] - mesh.vertices[s[0]]).norm();
        }
        return measure;
    }
    for (const auto& t : mesh.triangles) {
        const Vec3& a = mesh.vertices[t[0]];
        measure += 0.5 * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
    }
    for (const auto& q : mesh.quads) {
        const Vec3& a = mesh.vertices[q[0]];
        measure += 0.5 * (mesh.vertices[q[1]] - a).cross(mesh.vertices[q[2]] - a).norm();
        measure += 0.5 * (mesh.vertices[q[2]] - a).cross(mesh.vertices[q[3]] - a).norm();
    }
    return measure;
}

ParticleCount count_shape(const ShapeSettings& shape, double spacing, int dimension) {
    ParticleCount count;
    switch (shape.type) {
    case ShapeSettings::Type::box:
        count = count_box(shape.min, shape.max, spacing, dimension);
        break;
    case ShapeSettings::Type::mesh: {
        const double volume = enclosed_volume(shape.mesh);
        count.particles = volume / std::pow(spacing, 3);
        count.basis = "closed mesh of " + estimate_text(volume) + " m^3 / spacing^3";
        break;
    }
    case ShapeSettings::Type::lsdyna:
        count.particles = static_cast<double>(shape.deck_points.size());
        count.basis = "*ELEMENT_SPH cards of the deck";
        break;
    default:
        count = round_body(shape, spacing, dimension);
    }
    return count;
}

double ParticleEstimate::total() const {
    double sum = 0.0;
    for (const auto* list : {&bodies, &sources, &walls}) {
        for (const ParticleCount& count : *list) {
            sum += count.particles;
        }
    }
    return sum;
}

const ParticleCount* ParticleEstimate::largest() const {
    const ParticleCount* best = nullptr;
    for (const auto* list : {&bodies, &sources, &walls}) {
        for (const ParticleCount& count : *list) {
            if (best == nullptr || count.particles > best->particles) {
                best = &count;
            }
        }
    }
    return best;
}

} // namespace grainload::sph
