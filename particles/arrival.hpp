#pragma once
// A particle a scene part makes enter the scene, described whole.

#include "io/types.hpp"

#include <Eigen/Geometry>

namespace grainload::particles {

/// A particle a scene part (a source) is about to make enter: where, how fast, its mass, and
/// the body and material it belongs to (indices of the method's bodies and of the material
/// library), and a DEM grain's radius (0 for an SPH particle, whose size is the scene's
/// spacing) and orientation (a clump's; the identity for a sphere and an SPH particle). Whole,
/// so that the method creates it, and a restart replays it, from this alone.
struct Arrival {
    Vec3 position = Vec3::Zero();
    Vec3 velocity = Vec3::Zero();
    double mass = 0.0;
    int body = 0;
    int material = 0;
    double radius = 0.0;
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

} // namespace grainload::particles
