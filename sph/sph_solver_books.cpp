#include "particles/ordered_sum.hpp"
#include "sph/contact_force.hpp"
#include "sph/sph_solver.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

// The solver's books: the work the walls do, the energy the particles hold and the contact
// potential stores, momentum and strain energy, which the energy ledger and the tests read.

namespace grainload::sph {

double SphSolver::wall_work(double dt) const {
    // Every wall is booked, whatever moves it: a wall at rest has zero velocities and adds
    // nothing, and a driven wall (a shell) need not say how it moves.
    double power = wall_contact_.reaction_power_correction();
    for (const Wall& wall : walls_) {
        power -= particles::ordered_sum(wall.count, [&](Index k) {
            const Index i = wall.first + k;
            return particles_.mass[i] * particles_.acceleration[i].dot(particles_.velocity[i]);
        });
    }
    return dt * power;
}

double SphSolver::held_energy() const {
    return kinetic_energy() + internal_energy();
}

double SphSolver::contact_energy() const {
    return contact_energy_of({});
}

double SphSolver::contact_energy_of(std::span<const char> flagged) const {
    if (!(options_.contact.stiffness > 0.0)) {
        return 0.0;
    }
    const ParticleSet& p = particles_;
    const Index n = p.size();
    const double support_squared = kernel_.support_radius() * kernel_.support_radius();
    const double w_reference = kernel_.value(options_.particle_spacing);
    const bool all = flagged.empty();
    // Row by row, the rows in fixed blocks (particles/ordered_sum.hpp): the same bits on any
    // number of threads.
    auto row_energy = [&](Index i) {
        double sum = 0.0;
        const bool i_counts = all || flagged[i];
        // Pairs with images are held by the real particle's row only, so with images every row
        // is visited for them.
        if (!i_counts && images_.empty()) {
            return sum;
        }
        for (const Index entry : neighbours_.neighbours(i)) {
            // Entries from n on are images (outside a step the particle set holds none).
            const bool image = entry >= n;
            const GhostImage ghost = image ? images_[entry - n] : GhostImage{entry};
            const Index j = ghost.source;
            const bool j_counts = all || flagged[j];
            // The list holds each pair of two bodies twice (i in j's list and j in i's; only a
            // pair of one body is halved, sph/pair_parts.hpp): count it once, from a flagged
            // row, the lower index when both are flagged.
            const bool skip = image ? !(i_counts || j_counts) : !i_counts || (j < i && j_counts);
            if (skip || p.body_id[i] == p.body_id[j]) {
                continue;
            }
            // A pair of i and the image of grain j has the energy of the pair of j and the
            // image of i, and the full model holds each such pair once for two halves: half of
            // it is this side's. The image of a wall particle stands for that pair and for the
            // pair of the wall's real particle and the image of i, which no row holds: all of
            // it is this side's.
            const double share = image && !is_wall_[j] ? 0.5 : 1.0;
            const Vec3 xj = image ? image_position(p.position[j], ghost, frame_) : p.position[j];
            const double r2 = (p.position[i] - xj).squaredNorm();
            if (r2 < support_squared && r2 > 0.0) {
                const double volumes = p.mass[i] / p.density[i] * p.mass[j] / p.density[j];
                sum += share * sph::contact_energy(kernel_, options_.contact, w_reference, volumes,
                                                   std::sqrt(r2));
            }
        }
        return sum;
    };
    return particles::ordered_sum(n, row_energy, 0);
}

Vec3 SphSolver::linear_momentum() const {
    Vec3 sum = Vec3::Zero();
    for (Index i = 0; i < particles_.size(); ++i) {
        if (!is_wall_[i]) {
            sum += particles_.mass[i] * particles_.velocity[i];
        }
    }
    return sum;
}

Vec3 SphSolver::angular_momentum() const {
    Vec3 sum = Vec3::Zero();
    for (Index i = 0; i < particles_.size(); ++i) {
        if (!is_wall_[i]) {
            sum += particles_.mass[i] * particles_.position[i].cross(particles_.velocity[i]);
        }
    }
    return sum;
}

double SphSolver::kinetic_energy() const {
    return particles::ordered_sum(particles_.size(), [&](Index i) {
        return is_wall_[i] ? 0.0 : 0.5 * particles_.mass[i] * particles_.velocity[i].squaredNorm();
    });
}

double SphSolver::internal_energy() const {
    return particles::ordered_sum(particles_.size(), [&](Index i) {
        return is_wall_[i] ? 0.0 : particles_.mass[i] * particles_.internal_energy[i];
    });
}

double SphSolver::elastic_strain_energy() const {
    return particles::ordered_sum(particles_.size(), [&](Index i) {
        if (is_wall_[i]) {
            return 0.0;
        }
        const Voigt6& s = particles_.stress[i];
        const double volume = particles_.mass[i] / particles_.density[i];
        const auto& elastic =
            materials_[static_cast<std::size_t>(particles_.material_id[i])]->elastic();
        return 0.5 * volume * s.dot(elastic.strain_from_stress(s));
    });
}

} // namespace grainload::sph
