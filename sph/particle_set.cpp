#include "sph/particle_set.hpp"

#include <type_traits>

namespace grainload::sph {

namespace {

/// The zero of a field's value type (Eigen's default constructor leaves a vector unset).
template <class T> T zero_value() {
    if constexpr (std::is_arithmetic_v<T>) {
        return T{0};
    } else {
        return T::Zero();
    }
}

} // namespace

void ParticleSet::add(const Vec3& x, const Vec3& v, double particle_mass, double rho, int body,
                      int material, int state_size) {
    // Every registered field gets a zero entry; the ones a new particle does not start at zero
    // are set after, so a newly registered field starts at zero without a line here.
    for_each_field([](const auto& field, auto& values) {
        using T = typename std::remove_cvref_t<decltype(field)>::value_type;
        values.push_back(zero_value<T>());
    });
    position.back() = x;
    velocity.back() = v;
    mass.back() = particle_mass;
    density.back() = rho;
    body_id.back() = body;
    material_id.back() = material;
    wall_id.back() = -1;
    state_offset.back() = static_cast<Index>(state.size());
    state.resize(state.size() + static_cast<std::size_t>(state_size), 0.0);
}

void ParticleSet::add_wall_particle(const Vec3& x, const Vec3& v, double particle_mass, double rho,
                                    int body, int wall) {
    add(x, v, particle_mass, rho, body, -1, 0);
    wall_id.back() = wall;
}

void ParticleSet::reserve(Index n) {
    const auto count = static_cast<std::size_t>(n);
    for_each_field([count](const auto&, auto& values) { values.reserve(count); });
}

} // namespace grainload::sph
