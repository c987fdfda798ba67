#pragma once

#include "io/types.hpp"

#include <vector>

namespace grainload::sph {

/// All SPH particles of a scene, structure of arrays: one contiguous array per field, indexed
/// by particle. Positions are 3-vectors also in plane strain (dimension 2), where z stays 0.
/// Material state: particle i owns state[state_offset[i] .. state_offset[i] + its material's
/// state_size()), so bodies of different materials share one array.
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
    std::vector<double> state;

    Index size() const { return static_cast<Index>(position.size()); }
    /// Append one particle with zero stress and rates; state is sized by the caller.
    void add(const Vec3& x, const Vec3& v, double particle_mass, double rho, int body, int material,
             int state_size);
    /// Append one particle of rigid wall `wall` (no material, no state).
    void add_wall_particle(const Vec3& x, const Vec3& v, double particle_mass, double rho, int body,
                           int wall);
    bool is_wall(Index i) const { return wall_id[i] >= 0; }
    void reserve(Index n);
};

} // namespace grainload::sph
