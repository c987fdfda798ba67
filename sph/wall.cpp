#include "sph/wall.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace grainload::sph {

std::array<double, 4> face_weights(const WallSample& sample, int vertex_count) {
    const double r = sample.r;
    const double s = sample.s;
    if (vertex_count == 4) {
        return {(1.0 - r) * (1.0 - s), r * (1.0 - s), r * s, (1.0 - r) * s};
    }
    if (vertex_count == 3) {
        return {1.0 - r - s, r, s, 0.0};
    }
    return {1.0 - r, r, 0.0, 0.0};
}

// A driver without state beyond its particles' writes nothing.
void WallDriver::write_state(std::ostream&) const {}
void WallDriver::read_state(std::istream&) {}

Vec3 Wall::velocity_at(const ParticleSet& particles, Index k, const Vec3& x) const {
    const Vec3& v = particles.velocity[static_cast<std::size_t>(k)];
    if (angular_velocities.empty()) {
        return v;
    }
    const Vec3& omega = angular_velocities[static_cast<std::size_t>(k - first)];
    return v + omega.cross(x - particles.position[static_cast<std::size_t>(k)]);
}

Wall add_wall(ParticleSet& particles, std::string name, int wall_index, int body_id,
              const std::vector<Vec3>& points, double spacing, double density, int dimension) {
    Wall wall;
    wall.name = std::move(name);
    wall.body_id = body_id;
    wall.first = particles.size();
    wall.count = static_cast<Index>(points.size());
    const double mass = density * std::pow(spacing, dimension);
    Vec3 centre = Vec3::Zero();
    for (const Vec3& x : points) {
        particles.add_wall_particle(x, Vec3::Zero(), mass, density, body_id, wall_index);
        centre += x;
    }
    wall.centre = points.empty() ? centre : Vec3(centre / static_cast<double>(points.size()));
    return wall;
}

void accumulate_wall_load(const ParticleSet& particles, Wall& wall) {
    wall.force.setZero();
    wall.moment.setZero();
    for (Index k = wall.first; k < wall.first + wall.count; ++k) {
        const Vec3 f = particles.mass[k] * particles.acceleration[k];
        wall.force += f;
        wall.moment += (particles.position[k] - wall.centre).cross(f);
    }
}

} // namespace grainload::sph
