#pragma once
// A wall of the SPH scene: its particles, the driver that moves them, the load bodies put on it.

#include "sph/particle_set.hpp"

#include <array>
#include <cstdint>
#include <iosfwd>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace grainload::sph {

/// Where a wall particle was sampled from (a face of a surface mesh or a shell element), so
/// that one record serves both directions of a coupling: the face's motion onto the particle
/// and the particle's force back onto the face's vertices (coupling/).
///
/// Parametric point: a quadrangle a b c d is the bilinear patch
///   x(r, s) = (1-r)(1-s) a + r(1-s) b + r s c + (1-r) s d,  r, s in [0, 1];
/// a triangle a b c is x = (1 - r - s) a + r b + s c (barycentric); a segment a b (plane strain)
/// is x = (1 - r) a + r b. The particle lies at x(r, s) + offset * n, n the face's unit normal
/// (right-hand rule of the vertex order; the left side of a segment).
struct WallSample {
    Index face = -1; ///< face of the sampled surface; -1: not sampled from a surface
    double r = 0.0;
    double s = 0.0;
    int side = 1;        ///< +1: the material lies on the side n points to; -1: the other
    double offset = 0.0; ///< signed distance from the surface along n (behind it: -side)
    int layer = 0;       ///< 0 at the surface, then one per spacing behind it
};

/// The weights of the face's vertices at the sample's parametric point (the shape functions
/// N_a(r, s) of the face; 4 for a quadrangle, 3 and a zero for a triangle, 2 and zeros for a
/// segment), in the face's vertex order. They sum to 1.
std::array<double, 4> face_weights(const WallSample& sample, int vertex_count);

struct Wall;

/// Moves the particles of one wall: sets their positions, velocities and angular velocities
/// (Wall::angular_velocities) and the wall's normals at the end of a step. A rigid motion
/// (sph/rigid_wall.hpp) is one driver, a shell followed through the coupling another.
class WallDriver {
  public:
    virtual ~WallDriver() = default;
    /// From time t to t + dt; the particles hold their state at t.
    virtual void move(ParticleSet& particles, Wall& wall, double t, double dt) = 0;
    /// True when move() would change nothing, now and later (a wall at rest).
    virtual bool at_rest() const { return false; }
    /// Restart state beyond the particles' own (e.g. the rigid motion's centre).
    virtual void write_state(std::ostream& out) const;
    virtual void read_state(std::istream& in);
};

/// A wall of the SPH scene: particles [first, first + count) of the ParticleSet that bodies
/// feel through the contact potential, the dashpot and friction (sph/wall_contact.hpp), moved
/// by a driver. Its particles carry their own velocities in the ParticleSet; the wall holds
/// what only walls have.
struct Wall {
    std::string name;
    int body_id = -1; ///< distinct from every material body
    Index first = 0;
    Index count = 0;
    /// Unit normals of the wall surface at its particles, pointing into the material (empty:
    /// unknown; the contact normal then comes from the colour function). The driver turns them.
    std::vector<Vec3> normals;
    /// Angular velocity of the wall at each particle (empty: zero): the velocity of the wall at
    /// a point x near particle j is v_j + omega_j x (x - x_j), exact for a rigid motion.
    std::vector<Vec3> angular_velocities;
    /// Origin of each particle when sampled from a surface (empty otherwise).
    std::vector<WallSample> samples;
    Vec3 centre = Vec3::Zero(); ///< point about which `moment` is taken (the driver may move it)
    Vec3 force = Vec3::Zero();  ///< total force of the bodies on the wall (contact, dashpot,
                                ///< friction)
    Vec3 moment = Vec3::Zero(); ///< about `centre`
    /// Null: the wall never moves.
    std::shared_ptr<WallDriver> driver;
    /// The wall leaves the scene at the end of the first step that reaches this time (an
    /// outlet opened at once, [[sph.wall]] remove_at): its particles are removed, and the wall
    /// stays in the list with count 0. Infinity: never.
    double removal_time = std::numeric_limits<double>::infinity();
    /// remove_at = "settled": the wall leaves at the end of the step that settles the scene
    /// ([sph.settle]).
    bool removal_on_settle = false;
    /// remove_at = "phase:NAME": the phase whose start is removal_time (+infinity while that
    /// start is not known); -1: none.
    int removal_phase = -1;
    /// Material may lie on either side (a coupled shell with `side = "both"`: one layer on
    /// its mid-surface): the contact reads each particle's normal turned towards the material
    /// particle it pushes, so `normals` give the orientation only.
    bool two_sided = false;
    /// Symmetry planes ([[sph.symmetry]]) the wall is mirrored across: bit a for the plane
    /// normal to axis a (a wall that ends at the plane; one that runs on past it is not).
    std::uint8_t mirror_planes = 0;
    /// Body ids of the bodies the wall acts on ([[coupling.interface]] and [[sph.wall]]
    /// `bodies`); empty: all. The others pass through it as if it were not there: the solver
    /// leaves their pairs with its particles out of the neighbour list (SphSolver), so contact,
    /// damping, friction, the wall's load and the energy books all skip them.
    std::vector<int> bodies;

    /// Velocity of the wall at point x seen from its particle k (an index into the
    /// ParticleSet): v_k + omega_k x (x - x_k).
    Vec3 velocity_at(const ParticleSet& particles, Index k, const Vec3& x) const;
    bool moves() const { return driver && !driver->at_rest(); }
};

/// Append `points` to the particle set as wall `wall_index` (ParticleSet::wall_id) with body id
/// `body_id`, at rest. Wall particles get density `density` and mass density * spacing^dimension
/// (neither enters the physics: the contact potential uses volumes, V = spacing^dimension).
/// The centre (moment reference) is the points' centroid.
Wall add_wall(ParticleSet& particles, std::string name, int wall_index, int body_id,
              const std::vector<Vec3>& points, double spacing, double density, int dimension);

/// Sum mass * acceleration of the wall's particles (set by the force pass to the force the
/// bodies exert on them) into wall.force and wall.moment.
void accumulate_wall_load(const ParticleSet& particles, Wall& wall);

} // namespace grainload::sph
