#pragma once

#include "sph/particle_set.hpp"

#include <fstream>
#include <string>
#include <vector>

namespace grainload::sph {

/// A rigid wall made of layers of wall particles (thesis section 5.3: boundary particles) that
/// move with a prescribed rigid motion: translation velocity of `centre` and angular velocity
/// about it. Bodies feel the wall only through the contact potential.
struct RigidWall {
    std::string name;
    int body_id = -1; ///< distinct from every material body
    Vec3 centre = Vec3::Zero();
    Vec3 velocity = Vec3::Zero();
    Vec3 angular_velocity = Vec3::Zero();
    Index first = 0; ///< its particles are [first, first + count) of the ParticleSet
    Index count = 0;
    Vec3 force = Vec3::Zero();  ///< total contact force of the bodies on the wall
    Vec3 moment = Vec3::Zero(); ///< about `centre`
};

/// Particles for a plane wall: the parallelogram origin + s u + t v (s, t in [0, 1]; in plane
/// strain only u is used: a segment), repeated in `layers` layers behind it, i.e. against
/// `normal`, which points into the material. Lattice step `spacing`.
std::vector<Vec3> plane_wall_points(const Vec3& origin, const Vec3& u, const Vec3& v,
                                    const Vec3& normal, double spacing, int layers, int dimension);

/// Particles for a box container around the inner region [lower, upper]: `layers` layers
/// outside each face; `open_top` leaves out the face of largest y (2D) or z (3D).
std::vector<Vec3> box_wall_points(const Vec3& lower, const Vec3& upper, double spacing, int layers,
                                  int dimension, bool open_top);

/// Append `points` to the particle set as wall `wall_index` and return its RigidWall.
/// Wall particles get density `density` and mass density * spacing^dimension.
RigidWall add_rigid_wall(ParticleSet& particles, std::string name, int wall_index, int body_id,
                         const std::vector<Vec3>& points, double spacing, double density,
                         int dimension);

/// Move wall particles rigidly over dt (exact rotation about the moving centre) and set their
/// velocities to the rigid-body field.
void move_rigid_wall(ParticleSet& particles, RigidWall& wall, double dt);

/// Sum mass * acceleration of the wall's particles (set by the force pass to the contact force
/// the bodies exert on them) into wall.force and wall.moment.
void accumulate_wall_load(const ParticleSet& particles, RigidWall& wall);

/// DIR/wall_forces.csv: one row per wall and output instant.
class WallForceWriter {
  public:
    explicit WallForceWriter(const std::string& directory);
    void write(double time, const std::vector<RigidWall>& walls);

  private:
    std::ofstream out_;
};

} // namespace grainload::sph
