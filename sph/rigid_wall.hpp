#pragma once

#include "sph/particle_set.hpp"

#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace grainload::sph {

/// A rigid wall made of layers of wall particles (thesis section 5.3: boundary particles) that
/// move with a prescribed rigid motion: translation velocity of `centre` and angular velocity
/// about it. Bodies feel the wall only through the contact potential.
struct RigidWall {
    std::string name;
    int body_id = -1; ///< distinct from every material body
    Vec3 centre = Vec3::Zero();
    Vec3 velocity = Vec3::Zero();         ///< now; set from velocity_history when it has points
    Vec3 angular_velocity = Vec3::Zero(); ///< now; likewise
    /// Prescribed histories (time, value), piecewise linear, held before the first and after
    /// the last point; empty: the constant velocity / angular_velocity above.
    std::vector<std::pair<double, Vec3>> velocity_history;
    std::vector<std::pair<double, Vec3>> angular_velocity_history;
    Index first = 0; ///< its particles are [first, first + count) of the ParticleSet
    Index count = 0;
    /// Unit normals of the wall surface at its particles, pointing into the material (empty:
    /// unknown, and the contact normal comes from the colour function). They turn with it.
    std::vector<Vec3> normals;
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

/// Normals for box_wall_points: from each point towards the nearest point of [lower, upper]
/// (a face normal beside a face, the bisector beyond an edge or a corner).
std::vector<Vec3> box_wall_normals(const std::vector<Vec3>& points, const Vec3& lower,
                                   const Vec3& upper, int dimension);

/// Append `points` to the particle set as wall `wall_index` and return its RigidWall.
/// Wall particles get density `density` and mass density * spacing^dimension.
RigidWall add_rigid_wall(ParticleSet& particles, std::string name, int wall_index, int body_id,
                         const std::vector<Vec3>& points, double spacing, double density,
                         int dimension);

/// Value at `time` of a piecewise-linear history, held constant outside its points.
Vec3 history_value(const std::vector<std::pair<double, Vec3>>& history, double time);

/// Exact integral of the same function over [from, to].
Vec3 history_integral(const std::vector<std::pair<double, Vec3>>& history, double from, double to);

/// Move wall particles rigidly from `time` to `time + dt` and set their velocities to the
/// rigid-body field at the end. The centre moves by the exact integral of the velocity history
/// over the step, so it follows a piecewise-linear history to round-off at any dt. The rotation
/// is the exact rotation by the integrated angular velocity: exact while the axis is fixed
/// within a step, second order in dt otherwise.
void move_rigid_wall(ParticleSet& particles, RigidWall& wall, double time, double dt);

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
