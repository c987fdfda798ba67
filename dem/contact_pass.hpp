#pragma once
// One evaluation of every grain's force and torque: gravity, the sphere pairs, the walls.

#include "dem/contact_law.hpp"
#include "dem/grain_set.hpp"
#include "dem/plane_wall.hpp"
#include "dem/sphere_set.hpp"
#include "particles/neighbour_list.hpp"
#include "particles/wall_map.hpp"

#include <span>
#include <vector>

namespace grainload::dem {

/// What the pass saw, for the books and the diagnosis.
struct ContactBooks {
    double elastic_energy = 0.0; ///< held in the contacts' springs [J]
    Index pair_contacts = 0;     ///< between spheres of different grains
    Index wall_contacts = 0;
    double deepest_overlap = 0.0; ///< overlap / the smaller radius, largest over the contacts
    Index deepest_grain = -1;
};

/// The scene's fixed inputs to the pass.
struct ContactScene {
    const ContactLaw& law;
    /// E* and G* of each pair of bodies' grains (bodies x bodies, row-major), and of each
    /// body's grains on a wall: combined once, not at every contact.
    std::span<const PairProperties> body_pairs;
    std::span<const PairProperties> body_walls;
    Vec3 gravity;
};

/// One contact as the frames draw it: a line from the centre of the sphere it acts on to its
/// partner's centre (a wall's: the contact point), the force on that sphere, the normal from
/// the partner to it, and the overlap (negative: a cohesive pull across a gap).
struct ContactRecord {
    Vec3 from = Vec3::Zero();
    Vec3 to = Vec3::Zero();
    Vec3 force = Vec3::Zero();
    Vec3 normal = Vec3::Zero();
    double overlap = 0.0;
    bool wall = false;
};

/// A pair's contact as its sphere of the lower id evaluated it: what each of the two rows adds
/// (the force on a, or its opposite on b; each one's torque), for the other row to read.
struct PairResult {
    Vec3 force = Vec3::Zero();
    Vec3 torque_a = Vec3::Zero(); ///< added to a's torque
    Vec3 torque_b = Vec3::Zero(); ///< taken from b's torque
    double energy = 0.0;          ///< the contact's springs, booked by a
    double depth = 0.0;           ///< overlap over the smaller radius
    bool touching = false;        ///< else a cohesive pull across a gap
};

/// A grain's load on a wall: the force, and the sum of its contacts' normal forces (pushing
/// positive, a cohesive pull negative).
struct WallShare {
    Vec3 force = Vec3::Zero();
    double normal = 0.0;
    double elastic = 0.0;   ///< its contacts' normal springs' forces
    double stiffness = 0.0; ///< and their tangent stiffnesses
};

/// A contact's load on a following wall (PlaneWall::VertexMotion): its face, the contact
/// point's barycentric weights on the face's corners, the force on the wall and its moment about
/// the mid-surface.
struct VertexShare {
    std::uint32_t wall = 0;
    std::int32_t face = 0;
    Vec3 weights = Vec3::Zero();
    Vec3 force = Vec3::Zero();
    Vec3 moment = Vec3::Zero();
};

/// A contact's load on a wall a map reads ([[dem.wall_map]]): the wall and the load at the
/// contact point (the force on the wall, the normal from the wall into the material).
struct MappedLoad {
    std::uint32_t wall = 0;
    particles::WallLoad load;
};

/// The pass's per-sphere buffers, kept from one evaluation to the next so that a step
/// allocates nothing once the scene's size has settled.
struct ContactScratch {
    /// Whether the pass keeps `records`: each sphere's contacts (a pair in the row of its
    /// lower id), for the frames' contacts block.
    bool record = false;
    std::vector<std::vector<ContactRecord>> records;
    std::vector<Vec3> point_velocity; ///< each sphere centre's velocity, v + omega x arm
    std::vector<Vec3> force;          ///< each sphere's pair forces
    std::vector<Vec3> torque;         ///< about its centre
    std::vector<double> energy;
    std::vector<double> deepest;
    std::vector<std::vector<Spring>> kept; ///< the springs the step leaves, becoming the set's
    std::vector<WallShare> on_walls;       ///< each grain's load on each wall
    std::vector<std::vector<VertexShare>> vertex_shares; ///< each sphere's, with following walls
    /// Which walls a map reads (by wall; empty: none), and each sphere's loads on them.
    std::vector<char> mapped_walls;
    std::vector<std::vector<MappedLoad>> mapped_loads;
    std::vector<Index> first; ///< SphereSet::first_of_grains
    /// Per neighbour entry: whether the pair acts (set in the row of its lower id) and its
    /// result there; for each entry, the position of the same pair in the partner's row.
    std::vector<char> active;
    std::vector<PairResult> pairs;
    std::vector<Index> mirror;
    Index mirror_generation = -1; ///< the list's generation `mirror` was built for
};

/// Set grains.force and torque, and the spheres' contacts and springs, at the current
/// positions and velocities. Each pair of spheres of two grains is evaluated once, in the row
/// of its sphere of the lower id, oriented from it, which keeps the spring; then every row sums
/// its pairs in its own order, reading the other row's result through the list's mirror map,
/// so that the rows run in parallel with no shared writes, the two forces are exact opposites
/// (momentum kept to round-off) and no sum depends on the thread count. A grain's force is gravity
/// plus its spheres' forces, its torque their torques about its centre of mass (Markauskas, eqs. 7
/// and 8). Then the walls, grain by grain, with walls[w].force their sum. `neighbours` holds the
/// spheres' pairs, current for their positions.
ContactBooks evaluate_contacts(GrainSet& grains, SphereSet& spheres,
                               const particles::NeighbourList& neighbours,
                               std::vector<PlaneWall>& walls, const ContactScene& scene,
                               double time_step, ContactScratch& scratch);

} // namespace grainload::dem
