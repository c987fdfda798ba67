#include "sph/wall_contact.hpp"

#include "sph/contact_force.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace grainload::sph {

namespace {

/// What one body particle sees of one wall, summed over that wall's particles in its support.
struct WallTouch {
    int wall_index = -1; ///< index of the wall in the solver's wall list (ParticleSet::wall_id)
    Vec3 repulsion = Vec3::Zero();       ///< contact potential of the wall on i, eq. (5.3.12)
    Vec3 colour_gradient = Vec3::Zero(); ///< sum_j V_j grad_i W_ij, eq. (5.4.2)
    Mat3 stiffness = Mat3::Zero();       ///< sum_j k_ij e_ij e_ij^T
    Vec3 weighted_normal = Vec3::Zero(); ///< sum_j V_j W_ij n_j, walls that know their normals
    /// sum_j V_j W_ij (v_j + omega_j x (x_i - x_j)): the wall's velocity field at x_i
    Vec3 weighted_velocity = Vec3::Zero();
    double weight_sum = 0.0; ///< sum_j V_j W_ij
};

/// A particle rarely touches more than a floor and a side wall; a corner of a box touches three.
constexpr int kMaxWalls = 4;

const FrictionPair* pair_of(const SphOptions& options, int body, int wall_body) {
    for (const FrictionPair& pair : options.friction) {
        if (pair.body_id == body && pair.wall_body_id == wall_body) {
            return &pair;
        }
    }
    return nullptr;
}

WallTouch& touch_of(std::array<WallTouch, kMaxWalls>& walls, int& count, int wall_index) {
    for (int k = 0; k < count; ++k) {
        if (walls[k].wall_index == wall_index) {
            return walls[k];
        }
    }
    if (count < kMaxWalls) {
        walls[count] = WallTouch{};
        walls[count].wall_index = wall_index;
        return walls[count++];
    }
    // More walls than slots: the last slot pools the extra walls rather than drop their load.
    return walls[kMaxWalls - 1];
}

int gather_walls(const ParticleSet& p, Index i, const particles::NeighbourList& neighbours,
                 const SmoothingKernel& kernel, const SphOptions& options,
                 const std::vector<Wall>& rigid_walls, const WallImages& images,
                 std::array<WallTouch, kMaxWalls>& walls) {
    const double support_squared = kernel.support_radius() * kernel.support_radius();
    const double w_reference = kernel.value(options.particle_spacing);
    const double volume_i = p.mass[i] / p.density[i];
    int count = 0;
    for (const Index j : neighbours.neighbours(i)) {
        if (p.wall_id[j] < 0) {
            continue;
        }
        const Vec3 x_ij = p.position[i] - p.position[j];
        const double r2 = x_ij.squaredNorm();
        if (r2 >= support_squared || r2 == 0.0) {
            continue;
        }
        const double r = std::sqrt(r2);
        const Vec3 e = x_ij / r;
        const double volume_j = p.mass[j] / p.density[j];
        const double volumes = volume_i * volume_j;
        const double w = kernel.value(r);
        WallTouch& touch = touch_of(walls, count, p.wall_id[j]);
        touch.repulsion += contact_repulsion(kernel, options.contact, w_reference, volumes, r) * e;
        touch.colour_gradient += volume_j * kernel.gradient(x_ij, r);
        touch.stiffness.noalias() +=
            contact_stiffness(kernel, options.contact, w_reference, volumes, r) * e * e.transpose();
        const Wall& wall = rigid_walls[static_cast<std::size_t>(p.wall_id[j])];
        if (j >= images.first) { // an image of a wall particle (symmetry planes, periodic axes)
            const auto k = static_cast<std::size_t>(j - images.first);
            touch.weighted_normal += volume_j * w * images.normals[k]; // zero: none known
            touch.weighted_velocity +=
                volume_j * w * (p.velocity[j] + images.angular_velocities[k].cross(x_ij));
        } else {
            if (!wall.normals.empty()) {
                const Vec3& n = wall.normals[static_cast<std::size_t>(j - wall.first)];
                // A two-sided wall faces whichever side particle i is on.
                const double sign = wall.two_sided && n.dot(x_ij) < 0.0 ? -1.0 : 1.0;
                touch.weighted_normal += (sign * volume_j * w) * n;
            }
            touch.weighted_velocity += volume_j * w * wall.velocity_at(p, j, p.position[i]);
        }
        touch.weight_sum += volume_j * w;
    }
    return count;
}

/// Coulomb's law on the sliding velocity (see the class comment); returns the friction force
/// and counts the contact as stuck or slipping.
Vec3 coulomb_force(const FrictionPair& pair, double load, double mass, const Vec3& slip,
                   const Vec3& a_tangential, double dt, bool& stuck) {
    const Vec3 stick = -mass * (slip / dt + a_tangential);
    const double stick_norm = stick.norm();
    stuck = stick_norm <= pair.mu_static * load;
    return stuck ? stick : Vec3((pair.mu_kinetic * load / stick_norm) * stick);
}

/// What one wall does to particle i in a step of length dt.
struct TouchForce {
    Vec3 force = Vec3::Zero();         ///< the damper's and friction's, on the particle
    Vec3 wall_velocity = Vec3::Zero(); ///< the wall's velocity at the particle
    double friction_work = 0.0;
    double damping_work = 0.0;
    int sticking = 0; ///< 1 where friction held the particle, else 0
    int slipping = 0; ///< 1 where it slid
};

/// The contact damper (zeta > 0) and Coulomb friction (`pair`, or none) of one wall touching
/// particle i; the heat they make is taken off `heat` (the particle's, per unit mass times m).
TouchForce touch_force(const ParticleSet& p, Index i, const WallTouch& touch,
                       const FrictionPair* pair, double zeta, double dt, double& heat) {
    TouchForce out;
    const Vec3 direction = touch.weighted_normal.squaredNorm() > 0.0 ? touch.weighted_normal
                                                                     : Vec3(-touch.colour_gradient);
    const double direction_norm = direction.norm();
    if (!(direction_norm > 0.0) || !(touch.weight_sum > 0.0)) {
        return out;
    }
    const Vec3 normal = direction / direction_norm;
    // The wall's velocity at x_i, what a particle stuck to it moves with: the kernel average of
    // v_j + omega_j x (x_i - x_j) over its particles, exact for a rigid motion. (Their plain
    // mean would be the velocity below the surface, wrong by omega x (x_i - x_j) on a turning
    // wall.)
    out.wall_velocity = touch.weighted_velocity / touch.weight_sum;
    const Vec3 relative = p.velocity[i] - out.wall_velocity;
    const double normal_speed = relative.dot(normal);
    double load = touch.repulsion.dot(normal);
    if (zeta > 0.0) {
        // k_n = sum_j k_ij (e_ij . n)^2 >= 0, formed as n . K n: when every e_ij is nearly in
        // the wall's plane (a grain beside a wall's edge) round-off leaves that form a few ulps
        // of K below zero, and sqrt would make the damper, and the heat the grain books, NaN
        // (tests/unit/sph/wall_damper_test.cpp).
        const double k_n = std::max(normal.dot(touch.stiffness * normal), 0.0);
        const double damper =
            std::max(-2.0 * zeta * std::sqrt(k_n * p.mass[i]) * normal_speed, -load);
        out.force += damper * normal;
        load += damper;
        heat -= damper * normal_speed;
        out.damping_work = -damper * normal_speed * dt;
    }
    if (pair != nullptr && load > 0.0) {
        const Vec3 slip = relative - normal_speed * normal;
        const Vec3 a = p.acceleration[i] + out.force / p.mass[i];
        bool stuck = false;
        const Vec3 friction =
            coulomb_force(*pair, load, p.mass[i], slip, a - a.dot(normal) * normal, dt, stuck);
        (stuck ? out.sticking : out.slipping) = 1;
        out.force += friction;
        out.friction_work = -friction.dot(slip) * dt;
        heat -= friction.dot(slip);
    }
    return out;
}

} // namespace

void WallContact::apply(ParticleSet& p, const particles::NeighbourList& neighbours,
                        const SmoothingKernel& kernel, const SphOptions& options,
                        const std::vector<Wall>& rigid_walls, double dt,
                        std::vector<double>& heating_rate, const WallImages& images) {
    sticking_ = 0;
    slipping_ = 0;
    reaction_power_correction_ = 0.0;
    const double zeta = options.contact.damping_ratio;
    if ((options.friction.empty() && !(zeta > 0.0)) || !(dt > 0.0) ||
        !(options.contact.stiffness > 0.0)) {
        return;
    }
    int threads = 1;
#ifdef _OPENMP
    threads = omp_get_max_threads();
#endif
    per_thread_.resize(static_cast<std::size_t>(threads));
    find_particles_near_walls(p, neighbours);
    const Index n = p.size();
    Index sticking = 0;
    Index slipping = 0;
#pragma omp parallel reduction(+ : sticking, slipping)
    {
        int thread = 0;
#ifdef _OPENMP
        thread = omp_get_thread_num();
#endif
        auto& records = per_thread_[static_cast<std::size_t>(thread)];
        records.clear();
        std::array<WallTouch, kMaxWalls> walls;
#pragma omp for schedule(dynamic, 256)
        for (Index i = 0; i < n; ++i) {
            if (p.wall_id[i] >= 0 || near_wall_[static_cast<std::size_t>(i)] == 0) {
                continue;
            }
            const int count =
                gather_walls(p, i, neighbours, kernel, options, rigid_walls, images, walls);
            double heat = 0.0;
            for (int k = 0; k < count; ++k) {
                const WallTouch& touch = walls[k];
                const Wall& wall = rigid_walls[static_cast<std::size_t>(touch.wall_index)];
                const TouchForce t = touch_force(
                    p, i, touch, pair_of(options, p.body_id[i], wall.body_id), zeta, dt, heat);
                sticking += t.sticking;
                slipping += t.slipping;
                if (t.force.squaredNorm() > 0.0) {
                    p.acceleration[i] += t.force / p.mass[i];
                    records.push_back({i, touch.wall_index, t.force, touch.weight_sum,
                                       t.wall_velocity, t.friction_work, t.damping_work});
                }
            }
            heating_rate[static_cast<std::size_t>(i)] += heat / p.mass[i];
        }
    }
    sticking_ = sticking;
    slipping_ = slipping;
    distribute_reactions(p, neighbours, kernel);
}

void WallContact::find_particles_near_walls(const ParticleSet& p,
                                            const particles::NeighbourList& neighbours) {
    const Index n = p.size();
    if (near_wall_list_ == &neighbours && near_wall_generation_ == neighbours.generation() &&
        static_cast<Index>(near_wall_.size()) == n) {
        return;
    }
    near_wall_.assign(static_cast<std::size_t>(n), 0);
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        for (const Index j : neighbours.neighbours(i)) {
            if (p.wall_id[j] >= 0) {
                near_wall_[static_cast<std::size_t>(i)] = 1;
                break;
            }
        }
    }
    near_wall_list_ = &neighbours;
    near_wall_generation_ = neighbours.generation();
}

void WallContact::distribute_reactions(ParticleSet& p, const particles::NeighbourList& neighbours,
                                       const SmoothingKernel& kernel) {
    // Serial: only the contact layer has records, and wall particles are shared between
    // the records of neighbouring body particles. In the particles' order (each particle's
    // touches in the order found), whichever thread found them: the dynamic schedule hands
    // chunks to threads as they come free, so the threads' order would make the walls' loads,
    // and a coupled shell's, differ with the timing at round-off level, and a restart or a
    // second run would not repeat the run bit for bit.
    merged_.clear();
    for (const auto& records : per_thread_) {
        merged_.insert(merged_.end(), records.begin(), records.end());
    }
    std::stable_sort(merged_.begin(), merged_.end(),
                     [](const Record& a, const Record& b) { return a.particle < b.particle; });
    const double support_squared = kernel.support_radius() * kernel.support_radius();
    double friction_work = 0.0;
    double damping_work = 0.0;
    for (const Record& record : merged_) {
        friction_work += record.friction_work;
        damping_work += record.damping_work;
        const Index i = record.particle;
        Vec3 reaction_velocity = Vec3::Zero(); // share-weighted, the shares sum to 1
        for (const Index j : neighbours.neighbours(i)) {
            if (p.wall_id[j] != record.wall_index) {
                continue;
            }
            const double r2 = (p.position[i] - p.position[j]).squaredNorm();
            if (r2 >= support_squared) {
                continue;
            }
            const double share =
                p.mass[j] / p.density[j] * kernel.value(std::sqrt(r2)) / record.weight_sum;
            p.acceleration[j] -= (share / p.mass[j]) * record.force;
            reaction_velocity += share * p.velocity[j];
        }
        reaction_power_correction_ += record.force.dot(record.wall_velocity - reaction_velocity);
    }
    friction_work_ += friction_work;
    damping_work_ += damping_work;
}

} // namespace grainload::sph
