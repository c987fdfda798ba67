#include "sph/particle_set.hpp"

namespace grainload::sph {

void ParticleSet::add(const Vec3& x, const Vec3& v, double particle_mass, double rho, int body,
                      int material, int state_size) {
    position.push_back(x);
    velocity.push_back(v);
    acceleration.push_back(Vec3::Zero());
    mass.push_back(particle_mass);
    density.push_back(rho);
    density_rate.push_back(0.0);
    internal_energy.push_back(0.0);
    energy_rate.push_back(0.0);
    stress.push_back(Voigt6::Zero());
    strain_rate.push_back(Voigt6::Zero());
    spin.push_back(Vec3::Zero());
    plastic_strain.push_back(0.0);
    plastic_region.push_back(0);
    body_id.push_back(body);
    material_id.push_back(material);
    wall_id.push_back(-1);
    clamped.push_back(0);
    state_offset.push_back(static_cast<Index>(state.size()));
    state.resize(state.size() + static_cast<std::size_t>(state_size), 0.0);
}

void ParticleSet::add_wall_particle(const Vec3& x, const Vec3& v, double particle_mass, double rho,
                                    int body, int wall) {
    add(x, v, particle_mass, rho, body, -1, 0);
    wall_id.back() = wall;
}

void ParticleSet::reserve(Index n) {
    const auto count = static_cast<std::size_t>(n);
    position.reserve(count);
    velocity.reserve(count);
    acceleration.reserve(count);
    mass.reserve(count);
    density.reserve(count);
    density_rate.reserve(count);
    internal_energy.reserve(count);
    energy_rate.reserve(count);
    stress.reserve(count);
    strain_rate.reserve(count);
    spin.reserve(count);
    plastic_strain.reserve(count);
    plastic_region.reserve(count);
    body_id.reserve(count);
    material_id.reserve(count);
    wall_id.reserve(count);
    clamped.reserve(count);
    state_offset.reserve(count);
}

} // namespace grainload::sph
