#include "dem/contact_pass.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainload::dem {

namespace {

Vec3 spring_with(const std::vector<Spring>& springs, std::uint64_t partner) {
    const auto found =
        std::lower_bound(springs.begin(), springs.end(), partner,
                         [](const Spring& s, std::uint64_t key) { return s.partner < key; });
    return found != springs.end() && found->partner == partner ? found->shear : Vec3::Zero();
}

/// What one row (grain i) gathers.
struct RowResult {
    Vec3 force = Vec3::Zero();
    Vec3 torque = Vec3::Zero();
    int contacts = 0;
    double energy = 0.0;
    double deepest = 0.0;
};

/// Grain i's contacts with the other grains of its neighbour row.
void gather_pairs(const GrainSet& g, const particles::NeighbourList& neighbours,
                  const ContactScene& scene, double dt, Index i, std::vector<Spring>& kept,
                  RowResult& row) {
    for (const std::int32_t jj : neighbours.neighbours(i)) {
        const auto j = static_cast<Index>(jj);
        const double reach = g.radius[i] + g.radius[j];
        if ((g.position[i] - g.position[j]).squaredNorm() >= reach * reach) {
            continue;
        }
        const bool owner = g.id[i] < g.id[j];
        const Index a = owner ? i : j;
        const Index b = owner ? j : i;
        const Vec3 offset = g.position[a] - g.position[b];
        const double distance = offset.norm();
        ContactState state;
        state.normal = offset / distance;
        state.overlap = reach - distance;
        const double arm_a = g.radius[a] - 0.5 * state.overlap;
        const double arm_b = g.radius[b] - 0.5 * state.overlap;
        state.relative_velocity =
            g.velocity[a] - g.velocity[b] -
            (arm_a * g.angular_velocity[a] + arm_b * g.angular_velocity[b]).cross(state.normal);
        state.spring = spring_with(g.springs[a], g.id[b]);
        PairProperties pair;
        pair.mass = g.mass[a] * g.mass[b] / (g.mass[a] + g.mass[b]);
        pair.radius = g.radius[a] * g.radius[b] / reach;
        combine_elastic(scene.body_elastic[g.body_id[a]], scene.body_elastic[g.body_id[b]], pair);
        pair.friction = scene.law.friction;
        contact_force(scene.law, pair, dt, state);
        // Torque of the force on a at its contact point, -arm_a n from a's centre; b's by the
        // same force reversed at +arm_b n from b's centre: both are -arm n x F.
        const Vec3 turn = state.normal.cross(state.force);
        if (owner) {
            row.force += state.force;
            row.torque -= arm_a * turn;
            row.energy += state.elastic_energy;
            kept.push_back({g.id[j], state.spring});
        } else {
            row.force -= state.force;
            row.torque -= arm_b * turn;
        }
        ++row.contacts;
        row.deepest = std::max(row.deepest, state.overlap / std::min(g.radius[i], g.radius[j]));
    }
}

/// Grain i's contacts with the walls' faces: force and torque added to the grain's, springs
/// to `kept`, the force's opposite to the wall; returns the contacts.
int gather_walls(GrainSet& g, std::vector<PlaneWall>& walls, const ContactScene& scene, double dt,
                 Index i, std::vector<Spring>& kept, double& energy, double& deepest) {
    int contacts = 0;
    for (std::size_t w = 0; w < walls.size(); ++w) {
        if (walls[w].removed) {
            continue;
        }
        for (std::size_t f = 0; f < walls[w].faces.size(); ++f) {
            ContactState state;
            if (!touches(walls[w].faces[f], g.position[i], g.radius[i], state.overlap,
                         state.normal)) {
                continue;
            }
            const double arm = g.radius[i] - 0.5 * state.overlap;
            state.relative_velocity =
                g.velocity[i] - arm * g.angular_velocity[i].cross(state.normal);
            const std::uint64_t key = kWallPartner | (w << 8) | f;
            state.spring = spring_with(g.springs[i], key);
            PairProperties pair;
            pair.mass = g.mass[i];
            pair.radius = g.radius[i];
            combine_elastic(scene.body_elastic[g.body_id[i]], std::nullopt, pair);
            pair.friction = scene.law.wall_friction;
            contact_force(scene.law, pair, dt, state);
            g.force[i] += state.force;
            g.torque[i] -= arm * state.normal.cross(state.force);
            walls[w].force -= state.force;
            energy += state.elastic_energy;
            deepest = std::max(deepest, state.overlap / g.radius[i]);
            kept.push_back({key, state.spring});
            ++contacts;
        }
    }
    return contacts;
}

} // namespace

ContactBooks evaluate_contacts(GrainSet& g, const particles::NeighbourList& neighbours,
                               std::vector<PlaneWall>& walls, const ContactScene& scene,
                               double time_step) {
    const Index n = g.size();
    std::vector<std::vector<Spring>> kept(static_cast<std::size_t>(n));
    std::vector<double> energy(static_cast<std::size_t>(n), 0.0);
    std::vector<double> deepest(static_cast<std::size_t>(n), 0.0);
    Index pair_entries = 0;
#pragma omp parallel for schedule(static) reduction(+ : pair_entries)
    for (Index i = 0; i < n; ++i) {
        RowResult row;
        gather_pairs(g, neighbours, scene, time_step, i, kept[static_cast<std::size_t>(i)], row);
        g.force[i] = g.mass[i] * scene.gravity + row.force;
        g.torque[i] = row.torque;
        g.contacts[i] = row.contacts;
        energy[i] = row.energy;
        deepest[i] = row.deepest;
        pair_entries += row.contacts;
    }
    ContactBooks books;
    books.pair_contacts = pair_entries / 2;
    // The walls, grain by grain in order: their sums do not depend on the thread count.
    for (PlaneWall& wall : walls) {
        wall.force = Vec3::Zero();
    }
    for (Index i = 0; i < n; ++i) {
        const auto at = static_cast<std::size_t>(i);
        const int touching =
            gather_walls(g, walls, scene, time_step, i, kept[at], energy[at], deepest[at]);
        g.contacts[i] += touching;
        books.wall_contacts += touching;
        std::sort(kept[at].begin(), kept[at].end(),
                  [](const Spring& x, const Spring& y) { return x.partner < y.partner; });
        books.elastic_energy += energy[at];
        if (deepest[at] > books.deepest_overlap) {
            books.deepest_overlap = deepest[at];
            books.deepest_grain = i;
        }
    }
    g.springs = std::move(kept);
    return books;
}

} // namespace grainload::dem
