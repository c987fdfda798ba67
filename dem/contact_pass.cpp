#include "dem/contact_pass.hpp"

#include <algorithm>
#include <cmath>
#include <span>

namespace grainload::dem {

namespace {

/// Neighbouring mesh triangles whose normals' cosine reaches this lie on one surface for the
/// springs: 30 degrees, beyond a cylinder's facets (7.5 degrees at 48 around), short of a fold.
constexpr double kSameSurface = 0.8660254037844386;

/// The springs kept with `partner`, or unstretched ones for a new contact; whether kept.
bool springs_with(const std::vector<Spring>& springs, std::uint64_t partner, ContactState& state) {
    const auto found =
        std::lower_bound(springs.begin(), springs.end(), partner,
                         [](const Spring& s, std::uint64_t key) { return s.partner < key; });
    const bool kept = found != springs.end() && found->partner == partner;
    state.spring = kept ? found->shear : Vec3::Zero();
    state.rolling = kept ? found->rolling : Vec3::Zero();
    return kept;
}

/// The rolling dashpot's I + m r^2 of one side: a sphere of its grain's mass rolling on its
/// contact point.
double rolling_inertia(double mass, double radius) {
    return 1.4 * mass * radius * radius;
}

/// The pass's inputs and per-sphere results.
struct Pass {
    GrainSet& g;
    SphereSet& s;
    const ContactScene& scene;
    double dt;
    ContactScratch& x;
    std::size_t bodies;
};

/// The contact of spheres a (of the lower id) and b, `offset` = x_a - x_b apart, evaluated:
/// the force on a, its rolling torque and springs; `arm_a`, `arm_b` the contact point's
/// distances from their centres. Apart (overlap <= 0) they are within cohesion's reach.
ContactState pair_contact(const Pass& p, Index a, Index b, const Vec3& offset, double& arm_a,
                          double& arm_b) {
    const GrainSet& g = p.g;
    const SphereSet& s = p.s;
    const auto ga = static_cast<std::size_t>(s.grain[a]);
    const auto gb = static_cast<std::size_t>(s.grain[b]);
    const double touch = s.radius[a] + s.radius[b];
    const double distance = offset.norm();
    ContactState state;
    state.normal = offset / distance;
    state.overlap = touch - distance;
    arm_a = s.radius[a] - 0.5 * state.overlap;
    arm_b = s.radius[b] - 0.5 * state.overlap;
    state.relative_velocity =
        p.x.point_velocity[a] - p.x.point_velocity[b] -
        (arm_a * g.angular_velocity[ga] + arm_b * g.angular_velocity[gb]).cross(state.normal);
    if (state.overlap <= 0.0) {
        cohesive_force(p.scene.law, p.scene.law.cohesion_pull * std::min(g.mass[ga], g.mass[gb]),
                       state);
        return state;
    }
    state.relative_rotation = g.angular_velocity[ga] - g.angular_velocity[gb];
    springs_with(s.springs[a], s.id[b], state);
    PairProperties pair = p.scene.body_pairs[static_cast<std::size_t>(g.body_id[ga]) * p.bodies +
                                             static_cast<std::size_t>(g.body_id[gb])];
    pair.mass = g.mass[ga] * g.mass[gb] / (g.mass[ga] + g.mass[gb]);
    pair.radius = s.radius[a] * s.radius[b] / touch;
    if (pair.rolling_friction > 0.0) {
        const double ia = rolling_inertia(g.mass[ga], s.radius[a]);
        const double ib = rolling_inertia(g.mass[gb], s.radius[b]);
        pair.rolling_inertia = ia * ib / (ia + ib);
    }
    contact_force(p.scene.law, pair, p.dt, state);
    return state;
}

/// The pairs of sphere i's row that i owns (the lower id), evaluated where they act (touching,
/// or within cohesion's reach): their results in x.pairs, flagged in x.active; the owner's
/// springs kept and contacts recorded.
void solve_pairs(Pass& p, const particles::NeighbourList& neighbours, Index i) {
    const GrainSet& g = p.g;
    const SphereSet& s = p.s;
    const ContactLaw& law = p.scene.law;
    const auto at = static_cast<std::size_t>(i);
    const Index first = neighbours.first_entry(i);
    const auto row = neighbours.neighbours(i);
    for (std::size_t k = 0; k < row.size(); ++k) {
        const auto e = static_cast<std::size_t>(first) + k;
        p.x.active[e] = 0;
        const auto j = static_cast<Index>(row[k]);
        if (s.grain[i] == s.grain[j] || s.id[j] < s.id[i]) {
            continue;
        }
        const Vec3 offset = s.position[i] - s.position[j];
        double range = s.radius[i] + s.radius[j];
        if (law.cohesion_pull > 0.0) {
            range += cohesion_reach(law, law.cohesion_pull,
                                    std::min(g.mass[static_cast<std::size_t>(s.grain[i])],
                                             g.mass[static_cast<std::size_t>(s.grain[j])]));
        }
        if (offset.squaredNorm() >= range * range) {
            continue;
        }
        double arm_a = 0.0;
        double arm_b = 0.0;
        const ContactState state = pair_contact(p, i, j, offset, arm_a, arm_b);
        // Torque of the force on a at its contact point, -arm_a n from a's centre; b's by the
        // same force reversed at +arm_b n from b's centre: both are -arm n x F.
        const Vec3 turn = state.normal.cross(state.force);
        PairResult& result = p.x.pairs[e];
        result.force = state.force;
        result.torque_a = state.torque - arm_a * turn;
        result.torque_b = state.torque + arm_b * turn;
        result.energy = state.elastic_energy;
        result.touching = state.overlap > 0.0;
        result.depth = state.overlap / std::min(s.radius[i], s.radius[j]);
        p.x.active[e] = 1;
        if (result.touching) {
            p.x.kept[at].push_back({s.id[j], state.spring, state.rolling});
        }
        if (p.x.record && (result.touching || state.force != Vec3::Zero())) {
            p.x.records[at].push_back(
                {s.position[i], s.position[j], state.force, state.normal, state.overlap, false});
        }
    }
}

/// Sphere i's pairs with the spheres of other grains, summed in its row's order: its own
/// results and, through the mirror map, its partners'; returns the contacts.
int gather_pairs(Pass& p, const particles::NeighbourList& neighbours, Index i) {
    const SphereSet& s = p.s;
    const auto at = static_cast<std::size_t>(i);
    const Index first = neighbours.first_entry(i);
    const auto row = neighbours.neighbours(i);
    int contacts = 0;
    for (std::size_t k = 0; k < row.size(); ++k) {
        const auto j = static_cast<Index>(row[k]);
        if (s.grain[i] == s.grain[j]) {
            continue;
        }
        const bool owner = s.id[i] < s.id[j];
        const auto e =
            owner ? static_cast<std::size_t>(first) + k
                  : static_cast<std::size_t>(p.x.mirror[static_cast<std::size_t>(first) + k]);
        if (!p.x.active[e]) {
            continue;
        }
        const PairResult& result = p.x.pairs[e];
        if (owner) {
            p.x.force[at] += result.force;
            p.x.torque[at] += result.torque_a;
            p.x.energy[at] += result.energy;
        } else {
            p.x.force[at] -= result.force;
            p.x.torque[at] -= result.torque_b;
        }
        if (result.touching) {
            ++contacts;
            p.x.deepest[at] = std::max(p.x.deepest[at], result.depth);
        }
    }
    return contacts;
}

/// For each entry (i, j) of the list, the entry (j, i): the list holds each pair in both rows.
void build_mirror(const particles::NeighbourList& neighbours, Index n, std::vector<Index>& mirror) {
    mirror.assign(static_cast<std::size_t>(neighbours.pair_entries()), -1);
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        const auto row = neighbours.neighbours(i);
        for (std::size_t k = 0; k < row.size(); ++k) {
            const auto partner = neighbours.neighbours(row[k]);
            const auto found =
                std::find(partner.begin(), partner.end(), static_cast<std::int32_t>(i));
            mirror[static_cast<std::size_t>(neighbours.first_entry(i)) + k] =
                neighbours.first_entry(row[k]) + (found - partner.begin());
        }
    }
}

/// The spring key of face f of wall w.
std::uint64_t wall_key(std::size_t w, std::int32_t f) {
    return kWallPartner | (std::uint64_t{w} << 32) | static_cast<std::uint32_t>(f);
}

/// The springs sphere i keeps with face `touch.face` of wall w. A contact new to a mesh's
/// triangle takes over the springs of a neighbouring triangle it no longer touches whose plane
/// lies within 30 degrees of its own: a grain sliding over a tessellated surface keeps its
/// friction and rolling springs across the triangles' edges, as on one face.
void wall_springs(const Pass& p, const PlaneWall& wall, std::size_t w, Index i,
                  std::span<const PlaneWall::Touch> touched, std::int32_t face,
                  ContactState& state) {
    const auto& springs = p.s.springs[static_cast<std::size_t>(i)];
    if (springs_with(springs, wall_key(w, face), state) || !wall.mesh()) {
        return;
    }
    const Vec3& normal = wall.faces[static_cast<std::size_t>(face)].normal;
    for (const std::int32_t next : wall.adjacent[static_cast<std::size_t>(face)]) {
        const bool touched_too = std::any_of(touched.begin(), touched.end(),
                                             [next](const auto& t) { return t.face == next; });
        if (next < 0 || touched_too ||
            std::abs(normal.dot(wall.faces[static_cast<std::size_t>(next)].normal)) <
                kSameSurface) {
            continue;
        }
        if (springs_with(springs, wall_key(w, next), state)) {
            return;
        }
    }
}

/// Sphere i's contact with a face of wall w it touches or lies within cohesion's reach of
/// (`reach`; `touch` as PlaneWall::touching_faces gives it for radius + reach + the wall's half
/// thickness), evaluated; `face_velocity` that of a following wall's face where the sphere meets
/// it; `arm` the contact point's distance from its centre.
ContactState wall_contact(const Pass& p, const PlaneWall& wall, std::size_t w,
                          std::span<const PlaneWall::Touch> touched, const PlaneWall::Touch& touch,
                          Index i, double reach, const Vec3& face_velocity, double& arm) {
    const GrainSet& g = p.g;
    const SphereSet& s = p.s;
    const auto owner = static_cast<std::size_t>(s.grain[i]);
    const auto at = static_cast<std::size_t>(i);
    ContactState state;
    state.overlap = touch.overlap - reach;
    state.normal = touch.normal;
    arm = s.radius[i] - 0.5 * state.overlap;
    state.relative_velocity = p.x.point_velocity[at] - wall.current_velocity - face_velocity -
                              arm * g.angular_velocity[owner].cross(state.normal);
    if (state.overlap <= 0.0) {
        cohesive_force(p.scene.law, p.scene.law.wall_cohesion_pull * g.mass[owner], state);
        return state;
    }
    state.relative_rotation = g.angular_velocity[owner];
    wall_springs(p, wall, w, i, touched, touch.face, state);
    PairProperties pair = p.scene.body_walls[static_cast<std::size_t>(g.body_id[owner])];
    pair.mass = g.mass[owner];
    pair.radius = s.radius[i];
    pair.rolling_inertia = rolling_inertia(g.mass[owner], s.radius[i]);
    contact_force(p.scene.law, pair, p.dt, state);
    return state;
}

/// A contact's load `force` on face `touch.face` of the following wall w at its mid-surface
/// point `point`: its barycentric weights there, and its moment about the mid-surface, the
/// plate's face half the thickness off along the face's normal on the grain's side (the
/// shell's director: a moment normal to it, none about it, which a shell does not resist).
VertexShare vertex_share(const PlaneWall& wall, std::size_t w, const PlaneWall::Touch& touch,
                         const Vec3& point, const Vec3& force) {
    const Vec3& normal = wall.faces[static_cast<std::size_t>(touch.face)].normal;
    const double side = touch.normal.dot(normal) < 0.0 ? -1.0 : 1.0;
    return {static_cast<std::uint32_t>(w), touch.face, wall.barycentric(touch.face, point), force,
            (side * wall.half_thickness * normal).cross(force)};
}

/// Sphere i's contacts with the walls' faces: force and torque added to its grain's, springs
/// to its list, the force's opposite to its grain's share of each wall's load (`on_walls`, one
/// per wall); returns the contacts.
int gather_walls(Pass& p, const std::vector<PlaneWall>& walls, Index i, WallShare* on_walls) {
    GrainSet& g = p.g;
    const SphereSet& s = p.s;
    const auto owner = static_cast<std::size_t>(s.grain[i]);
    const auto at = static_cast<std::size_t>(i);
    const double reach = cohesion_reach(p.scene.law, p.scene.law.wall_cohesion_pull, g.mass[owner]);
    thread_local std::vector<PlaneWall::Touch> touched;
    int contacts = 0;
    for (std::size_t w = 0; w < walls.size(); ++w) {
        const PlaneWall& wall = walls[w];
        if (wall.removed) {
            continue;
        }
        const Vec3 centre = s.position[i] - wall.displacement;
        const double reaches = s.radius[i] + reach + wall.half_thickness;
        wall.touching_faces(centre, reaches, touched);
        for (const PlaneWall::Touch& touch : touched) {
            // A following wall: where on its face's mid-surface the sphere meets it.
            const Vec3 point = centre - (reaches - touch.overlap) * touch.normal;
            double arm = 0.0;
            const ContactState state = wall_contact(
                p, wall, w, touched, touch, i, reach,
                wall.follows() ? wall.face_velocity(touch.face, point) : Vec3::Zero(), arm);
            g.force[owner] += state.force;
            g.torque[owner] += state.torque - arm * state.normal.cross(state.force);
            g.torque[owner] += s.arm[at].cross(state.force);
            on_walls[w].force -= state.force;
            on_walls[w].normal += state.force.dot(state.normal);
            on_walls[w].elastic += state.elastic_n;
            on_walls[w].stiffness += state.stiffness_n;
            if (wall.follows() && state.force != Vec3::Zero()) {
                p.x.vertex_shares[at].push_back(vertex_share(wall, w, touch, point, -state.force));
            }
            if (w < p.x.mapped_walls.size() && p.x.mapped_walls[w] != 0 &&
                state.force != Vec3::Zero()) {
                p.x.mapped_loads[at].push_back(
                    {static_cast<std::uint32_t>(w),
                     {s.position[i] - arm * state.normal, state.normal, -state.force}});
            }
            p.x.energy[at] += state.elastic_energy;
            if (p.x.record && (state.overlap > 0.0 || state.force != Vec3::Zero())) {
                p.x.records[at].push_back({s.position[i], s.position[i] - arm * state.normal,
                                           state.force, state.normal, state.overlap, true});
            }
            if (state.overlap > 0.0) {
                p.x.deepest[at] = std::max(p.x.deepest[at], state.overlap / s.radius[i]);
                p.x.kept[at].push_back({wall_key(w, touch.face), state.spring, state.rolling});
                ++contacts;
            }
        }
    }
    return contacts;
}

/// The following walls' vertex loads: each contact's force and moment shared among its face's
/// corners by its barycentric weights, sphere by sphere in order (no sum depends on the thread
/// count).
void share_vertex_loads(const std::vector<std::vector<VertexShare>>& shares,
                        std::vector<PlaneWall>& walls) {
    for (PlaneWall& wall : walls) {
        if (wall.follows()) {
            std::fill(wall.vertices.force.begin(), wall.vertices.force.end(), Vec3::Zero());
            std::fill(wall.vertices.moment.begin(), wall.vertices.moment.end(), Vec3::Zero());
        }
    }
    for (const auto& row : shares) {
        for (const VertexShare& share : row) {
            PlaneWall::VertexMotion& v = walls[share.wall].vertices;
            const auto& corners = v.corners[static_cast<std::size_t>(share.face)];
            for (int k = 0; k < 3; ++k) {
                const auto at = static_cast<std::size_t>(corners[static_cast<std::size_t>(k)]);
                v.force[at] += share.weights[k] * share.force;
                v.moment[at] += share.weights[k] * share.moment;
            }
        }
    }
}

/// Bins the faces of the mesh walls for the farthest reach of any sphere (its radius and
/// cohesion's reach), a quarter more to spare rebuilding as grains arrive; rebuilt only when a
/// sphere reaches farther. The grid selects faces only: no result depends on when it was built.
void index_mesh_walls(const GrainSet& g, const SphereSet& s, std::vector<PlaneWall>& walls,
                      const ContactLaw& law) {
    if (std::none_of(walls.begin(), walls.end(), [](const PlaneWall& w) { return w.mesh(); })) {
        return;
    }
    double farthest = 0.0;
    for (Index i = 0; i < s.size(); ++i) {
        const double mass = g.mass[static_cast<std::size_t>(s.grain[i])];
        farthest =
            std::max(farthest, s.radius[i] + cohesion_reach(law, law.wall_cohesion_pull, mass));
    }
    for (PlaneWall& wall : walls) {
        if (wall.mesh() && wall.grid.reach() < farthest + wall.half_thickness) {
            wall.index_faces(1.25 * farthest + wall.half_thickness);
        }
    }
}

/// The pass's scratch sized for the spheres, the grains and the walls (and the mesh walls'
/// faces indexed); whether a wall follows its mesh's vertices (then their loads are shared out).
bool size_scratch(GrainSet& g, SphereSet& s, std::vector<PlaneWall>& walls,
                  const ContactScene& scene, ContactScratch& scratch) {
    const auto count = static_cast<std::size_t>(s.size());
    scratch.point_velocity.resize(count);
    scratch.force.resize(count);
    scratch.torque.resize(count);
    scratch.energy.resize(count);
    scratch.deepest.resize(count);
    scratch.kept.resize(count);
    scratch.records.resize(scratch.record ? count : 0);
    const bool following =
        std::any_of(walls.begin(), walls.end(), [](const PlaneWall& w) { return w.follows(); });
    scratch.vertex_shares.resize(following ? count : 0);
    scratch.mapped_loads.resize(scratch.mapped_walls.empty() ? 0 : count);
    index_mesh_walls(g, s, walls, scene.law);
    scratch.on_walls.assign(static_cast<std::size_t>(g.size()) * walls.size(), WallShare{});
    s.first_of_grains(g.size(), scratch.first);
    return following;
}

/// Each sphere's contact point velocity from its grain's motion, and its sums cleared.
void clear_sphere_sums(Pass& p) {
    const Index n = p.s.size();
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        const auto owner = static_cast<std::size_t>(p.s.grain[i]);
        p.x.point_velocity[i] = p.g.velocity[owner] + p.g.angular_velocity[owner].cross(p.s.arm[i]);
        p.x.force[i] = Vec3::Zero();
        p.x.torque[i] = Vec3::Zero();
        p.x.energy[i] = 0.0;
        p.x.deepest[i] = 0.0;
        p.x.kept[i].clear();
        if (!p.x.vertex_shares.empty()) {
            p.x.vertex_shares[i].clear();
        }
        if (p.x.record) {
            p.x.records[i].clear();
        }
        if (!p.x.mapped_loads.empty()) {
            p.x.mapped_loads[i].clear();
        }
    }
}

/// Each grain's force and torque: gravity, then its spheres' sums in order (eqs. 7 and 8 of
/// Markauskas), then its spheres' contacts with the walls; returns the wall contacts.
Index sum_grains(Pass& p, std::vector<PlaneWall>& walls) {
    GrainSet& g = p.g;
    SphereSet& s = p.s;
    const std::vector<Index>& first = p.x.first;
    const std::size_t wall_count = walls.size();
    Index wall_contacts = 0;
#pragma omp parallel for schedule(static) reduction(+ : wall_contacts)
    for (Index k = 0; k < g.size(); ++k) {
        g.force[k] = g.mass[k] * p.scene.gravity;
        g.torque[k] = Vec3::Zero();
        for (Index i = first[k]; i < first[k + 1]; ++i) {
            g.force[k] += p.x.force[i];
            g.torque[k] += p.x.torque[i] + s.arm[i].cross(p.x.force[i]);
        }
        for (Index i = first[k]; i < first[k + 1]; ++i) {
            const int touching = gather_walls(p, walls, i, p.x.on_walls.data() + k * wall_count);
            s.contacts[i] += touching;
            wall_contacts += touching;
            auto& kept = p.x.kept[static_cast<std::size_t>(i)];
            std::sort(kept.begin(), kept.end(),
                      [](const Spring& x, const Spring& y) { return x.partner < y.partner; });
        }
    }
    return wall_contacts;
}

/// The walls' loads, grain by grain in order: their sums do not depend on the thread count.
void book_walls(const ContactScratch& scratch, Index grains, std::vector<PlaneWall>& walls,
                bool following) {
    const std::size_t wall_count = walls.size();
    for (std::size_t w = 0; w < wall_count; ++w) {
        walls[w].force = Vec3::Zero();
        walls[w].normal_force = 0.0;
        walls[w].elastic_normal_force = 0.0;
        walls[w].normal_stiffness = 0.0;
        for (Index k = 0; k < grains; ++k) {
            const WallShare& share = scratch.on_walls[static_cast<std::size_t>(k) * wall_count + w];
            walls[w].force += share.force;
            walls[w].normal_force += share.normal;
            walls[w].elastic_normal_force += share.elastic;
            walls[w].normal_stiffness += share.stiffness;
        }
    }
    if (following) {
        share_vertex_loads(scratch.vertex_shares, walls);
    }
}

} // namespace

ContactBooks evaluate_contacts(GrainSet& g, SphereSet& s,
                               const particles::NeighbourList& neighbours,
                               std::vector<PlaneWall>& walls, const ContactScene& scene,
                               double time_step, ContactScratch& scratch) {
    const Index n = s.size();
    const bool following = size_scratch(g, s, walls, scene, scratch);
    Pass p{g, s, scene, time_step, scratch, scene.body_walls.size()};
    clear_sphere_sums(p);
    if (scratch.mirror_generation != neighbours.generation() ||
        scratch.mirror.size() != static_cast<std::size_t>(neighbours.pair_entries())) {
        build_mirror(neighbours, n, scratch.mirror);
        scratch.mirror_generation = neighbours.generation();
    }
    scratch.active.resize(static_cast<std::size_t>(neighbours.pair_entries()));
    scratch.pairs.resize(static_cast<std::size_t>(neighbours.pair_entries()));
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        solve_pairs(p, neighbours, i);
    }
    Index pair_entries = 0;
#pragma omp parallel for schedule(static) reduction(+ : pair_entries)
    for (Index i = 0; i < n; ++i) {
        s.contacts[i] = gather_pairs(p, neighbours, i);
        pair_entries += s.contacts[i];
    }
    ContactBooks books;
    books.pair_contacts = pair_entries / 2;
    books.wall_contacts = sum_grains(p, walls);
    book_walls(scratch, g.size(), walls, following);
    for (Index i = 0; i < n; ++i) {
        const auto at = static_cast<std::size_t>(i);
        books.elastic_energy += p.x.energy[at];
        if (p.x.deepest[at] > books.deepest_overlap) {
            books.deepest_overlap = p.x.deepest[at];
            books.deepest_grain = s.grain[i];
        }
    }
    // The new springs become the set's; the old rows, cleared at the next pass, keep their
    // memory for it.
    s.springs.swap(scratch.kept);
    return books;
}

} // namespace grainload::dem
