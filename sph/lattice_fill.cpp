#include "sph/lattice_fill.hpp"

#include "sph/body_generator.hpp"

#include <cmath>

namespace grainload::sph {

Index fill_box_lattice(ParticleSet& particles, const LatticeBody& body, int dimension) {
    const auto points = fill_box(body.lower, body.upper, body.spacing, dimension);
    const double mass = body.density * std::pow(body.spacing, dimension);
    particles.reserve(particles.size() + static_cast<Index>(points.size()));
    for (const Vec3& x : points) {
        particles.add(x, body.velocity, mass, body.density, body.body_id, body.material_id,
                      body.state_size);
    }
    return static_cast<Index>(points.size());
}

} // namespace grainload::sph
