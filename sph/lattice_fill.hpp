#pragma once
// A body of particles on a regular lattice filling a box.

#include "sph/particle_set.hpp"

namespace grainload::sph {

/// A body on a regular lattice: particles at the centres of the cells of size `spacing` that
/// tile [lower, upper] (z ignored in plane strain). Mass = density * spacing^dimension (per unit
/// thickness in plane strain). Returns the number of particles added.
struct LatticeBody {
    Vec3 lower = Vec3::Zero();
    Vec3 upper = Vec3::Zero();
    double spacing = 0.0;
    double density = 0.0;
    Vec3 velocity = Vec3::Zero();
    int body_id = 0;
    int material_id = 0;
    int state_size = 0;
};

Index fill_box_lattice(ParticleSet& particles, const LatticeBody& body, int dimension);

} // namespace grainload::sph
