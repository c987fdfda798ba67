#pragma once
// All SPH particles of a scene, one contiguous array per field (structure of arrays).

#include "io/types.hpp"
#include "particles/particle_view.hpp"

#include <cstddef>
#include <tuple>
#include <vector>

namespace grainload::sph {

/// How a per-particle field's value transforms when a particle is mirrored in a symmetry plane
/// (sph/symmetry.hpp: the image of particle s carries the transformed values of s).
enum class Mirror {
    copy,    ///< invariant: scalars, flags, indices
    point,   ///< a position: reflected about the plane
    polar,   ///< a polar vector (velocity): the component normal to the plane flips
    axial,   ///< an axial vector (spin): the components in the plane flip
    tensor,  ///< a symmetric tensor in Voigt order: the shear components across the plane flip
    cleared, ///< reset to zero on the image (a clamp holds only real particles)
};

/// All SPH particles of a scene, structure of arrays: one contiguous array per field, indexed
/// by particle. Positions are 3-vectors also in plane strain (dimension 2), where z stays 0.
/// Material state: particle i owns state[state_offset[i] .. state_offset[i] + its material's
/// state_size()), so bodies of different materials share one array.
///
/// Every array with one entry per particle is registered once, in `particle_fields` below the
/// struct; adding, reserving, removing particles and writing symmetry images visit that list
/// (for_each_field), so a new field is a member here plus one line there. A member that is not
/// registered fails the static_assert after the list.
struct ParticleSet {
    std::vector<Vec3> position;
    std::vector<Vec3> velocity;
    std::vector<Vec3> acceleration;
    std::vector<double> mass;
    std::vector<double> density;
    std::vector<double> density_rate;
    std::vector<double> internal_energy; ///< specific, J/kg
    std::vector<double> energy_rate;
    std::vector<Voigt6> stress;         ///< Cauchy, tension positive, tensor shear
    std::vector<Voigt6> strain_rate;    ///< engineering shear
    std::vector<Vec3> spin;             ///< axial vector of the spin tensor
    std::vector<double> plastic_strain; ///< equivalent plastic strain, for output
    std::vector<int> plastic_region;    ///< materials::PlasticRegion of the last update
    std::vector<int> body_id;
    std::vector<int> material_id;
    /// Index of the rigid wall a wall particle belongs to; -1 for material particles. Wall
    /// particles move kinematically and interact with bodies only through the contact potential.
    std::vector<int> wall_id;
    /// 1: a clamped material particle ([[sph.body.clamp]]), whose velocity the integrator holds
    /// at zero while it still takes part in every SPH sum (the built-in root of a cantilever).
    std::vector<char> clamped;
    std::vector<Index> state_offset;
    /// Not a registered field: its length is the sum of the particles' state sizes (each
    /// material has its own), not the particle count, so appending and removing handle it
    /// through state_offset (ParticleSet::add, sph/particle_removal.cpp).
    std::vector<double> state;

    Index size() const { return static_cast<Index>(position.size()); }
    /// Append one particle with zero stress and rates; state is sized by the caller.
    void add(const Vec3& x, const Vec3& v, double particle_mass, double rho, int body, int material,
             int state_size);
    /// Append one particle of rigid wall `wall` (no material, no state).
    void add_wall_particle(const Vec3& x, const Vec3& v, double particle_mass, double rho, int body,
                           int wall);
    bool is_wall(Index i) const { return wall_id[i] >= 0; }
    /// The fields every particle method shares, for the scene parts of the particles floor.
    particles::ParticleView view() const { return {position, mass, body_id, wall_id}; }
    void reserve(Index n);

    /// Call f(field, values) for every registered per-particle field, in registration order:
    /// `field` is its ParticleField entry (name, Mirror rule), `values` the member array.
    template <class F> void for_each_field(F&& f);
    template <class F> void for_each_field(F&& f) const;
};

/// One registered per-particle field: its name (for messages and tests), the member array,
/// and how its values transform in a symmetry plane (a compile-time constant, so that
/// sph/symmetry.cpp can check the rule fits the value type).
template <class T, Mirror M> struct ParticleField {
    using value_type = T;
    static constexpr Mirror mirror = M;
    const char* name;
    std::vector<T> ParticleSet::*values;
};

/// The registry: every array of ParticleSet with one entry per particle, once.
inline constexpr auto particle_fields = std::make_tuple(
    ParticleField<Vec3, Mirror::point>{"position", &ParticleSet::position},
    ParticleField<Vec3, Mirror::polar>{"velocity", &ParticleSet::velocity},
    ParticleField<Vec3, Mirror::polar>{"acceleration", &ParticleSet::acceleration},
    ParticleField<double, Mirror::copy>{"mass", &ParticleSet::mass},
    ParticleField<double, Mirror::copy>{"density", &ParticleSet::density},
    ParticleField<double, Mirror::copy>{"density_rate", &ParticleSet::density_rate},
    ParticleField<double, Mirror::copy>{"internal_energy", &ParticleSet::internal_energy},
    ParticleField<double, Mirror::copy>{"energy_rate", &ParticleSet::energy_rate},
    ParticleField<Voigt6, Mirror::tensor>{"stress", &ParticleSet::stress},
    ParticleField<Voigt6, Mirror::tensor>{"strain_rate", &ParticleSet::strain_rate},
    ParticleField<Vec3, Mirror::axial>{"spin", &ParticleSet::spin},
    ParticleField<double, Mirror::copy>{"plastic_strain", &ParticleSet::plastic_strain},
    ParticleField<int, Mirror::copy>{"plastic_region", &ParticleSet::plastic_region},
    ParticleField<int, Mirror::copy>{"body_id", &ParticleSet::body_id},
    ParticleField<int, Mirror::copy>{"material_id", &ParticleSet::material_id},
    ParticleField<int, Mirror::copy>{"wall_id", &ParticleSet::wall_id},
    ParticleField<char, Mirror::cleared>{"clamped", &ParticleSet::clamped},
    // An image shares its source's state block (images are never integrated or updated).
    ParticleField<Index, Mirror::copy>{"state_offset", &ParticleSet::state_offset});

inline constexpr std::size_t particle_field_count = std::tuple_size_v<decltype(particle_fields)>;

// ParticleSet holds only std::vectors (all of one size whatever their element type): the
// registered fields and `state`. A member added without its line in particle_fields changes
// sizeof and stops the build here.
static_assert(sizeof(ParticleSet) == (particle_field_count + 1) * sizeof(std::vector<char>),
              "every per-particle member of ParticleSet must be registered in particle_fields");

template <class F> void ParticleSet::for_each_field(F&& f) {
    std::apply([&](const auto&... field) { (f(field, this->*field.values), ...); },
               particle_fields);
}

template <class F> void ParticleSet::for_each_field(F&& f) const {
    std::apply([&](const auto&... field) { (f(field, this->*field.values), ...); },
               particle_fields);
}

} // namespace grainload::sph
