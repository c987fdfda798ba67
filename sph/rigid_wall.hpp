#pragma once
// The prescribed rigid motion of a wall: translation and rotation, constant or from histories.

#include "sph/particle_set.hpp"
#include "sph/wall.hpp"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace grainload::sph {

/// The prescribed rigid motion of a wall (thesis section 5.3: boundary particles moved
/// kinematically): translation velocity of `centre` and angular velocity about it, constant or
/// following piecewise-linear histories.
class RigidMotion final : public WallDriver {
  public:
    Vec3 centre = Vec3::Zero();
    Vec3 velocity = Vec3::Zero();         ///< now; set from velocity_history when it has points
    Vec3 angular_velocity = Vec3::Zero(); ///< now; likewise
    /// Prescribed histories (time, value), piecewise linear, held before the first and after
    /// the last point; empty: the constant velocity / angular_velocity above.
    std::vector<std::pair<double, Vec3>> velocity_history;
    std::vector<std::pair<double, Vec3>> angular_velocity_history;
    /// Histories that count from a phase's start ([[sph.wall]] history_start = "phase:NAME"):
    /// the phase, and the histories as the case gives them; the two above stay empty (the
    /// wall holds the velocities above, their first values) until start_histories() places
    /// them. -1: none.
    int history_phase = -1;
    std::vector<std::pair<double, Vec3>> relative_velocity_history;
    std::vector<std::pair<double, Vec3>> relative_angular_velocity_history;

    /// Place the relative histories at `start` (their times plus start); +infinity: not yet.
    void start_histories(double start);

    /// Moves the wall's particles rigidly from `time` to `time + dt` and sets their velocities
    /// and angular velocities to the rigid-body field at the end. The centre moves by the exact
    /// integral of the velocity history over the step, so it follows a piecewise-linear history
    /// to round-off at any dt. The rotation is the exact rotation by the integrated angular
    /// velocity: exact while the axis is fixed within a step, second order in dt otherwise.
    /// The wall's moment reference follows the centre.
    void move(ParticleSet& particles, Wall& wall, double time, double dt) override;
    bool at_rest() const override;
    void write_state(std::ostream& out) const override;
    void read_state(std::istream& in) override;
};

/// Attach a rigid motion about the wall's centre (its centroid unless moved) with the given
/// constant velocities, and set its particles' velocities to the rigid field.
RigidMotion& attach_rigid_motion(ParticleSet& particles, Wall& wall, const Vec3& velocity,
                                 const Vec3& angular_velocity);

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

/// Value at `time` of a piecewise-linear history, held constant outside its points.
Vec3 history_value(const std::vector<std::pair<double, Vec3>>& history, double time);

/// Exact integral of the same function over [from, to].
Vec3 history_integral(const std::vector<std::pair<double, Vec3>>& history, double from, double to);

/// wall_forces.csv, streamed into the run's output: its header, and its rows at one output
/// instant, one per wall.
inline constexpr std::string_view kWallForcesHeader =
    "time_s,wall,force_x_N,force_y_N,force_z_N,moment_x_Nm,moment_y_Nm,moment_z_Nm\n";
std::string wall_force_rows(double time, const std::vector<Wall>& walls);

} // namespace grainload::sph
