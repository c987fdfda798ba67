// SphModel's outlets: particles leaving through [[sph.sink]] regions and walls removed at a
// time ([[sph.wall]] remove_at), with their checkpoint state. The rest of SphModel is in
// sph_model.cpp.
#include "io/binary_stream.hpp"
#include "particles/mass_audit.hpp"
#include "sph/gates.hpp"
#include "sph/particle_removal.hpp"
#include "sph/sph_model.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

namespace grainload::sph {

void SphModel::set_sinks(std::shared_ptr<particles::SinkSet> sinks) {
    sinks_ = std::move(sinks);
    if (!sinks_->empty()) {
        parts_.add(sinks_);
    }
}

void SphModel::set_settle(const particles::SettleWatch& watch) {
    auto part = std::make_shared<particles::SettlePart>(
        watch, [this] { return solver_->kinetic_energy(); });
    settle_ = part;
    parts_.add(std::move(part));
}

void SphModel::add_gates() {
    const bool walls_go = solver_ && GateSet::any(solver_->walls());
    if (walls_go) {
        parts_.add(std::make_shared<GateSet>(solver_->walls(), settle_));
    }
    removals_ = !sinks_->empty() || walls_go;
}

void SphModel::open_books() {
    audit_ = removals_ || !sources_->empty();
    built_count_ = particles().size();
    const ParticleSet& p = particles();
    std::set<int> used;
    for (Index i = 0; i < p.size(); ++i) {
        if (!p.is_wall(i)) {
            used.insert(p.material_id[i]);
        }
    }
    built_materials_.assign(used.begin(), used.end());
    origin_.resize(static_cast<std::size_t>(particles().size()));
    std::iota(origin_.begin(), origin_.end(), Index{0});
    if (audit_) {
        parts_.add(std::make_shared<particles::MassAudit>(
            scene_mass(), dimension_,
            particles::MassAudit::Books{[this] { return scene_mass(); },
                                        [this] { return sinks_->discharged(); },
                                        [this] { return sources_->created(); }}));
    }
}

double SphModel::scene_mass() const {
    const ParticleSet& p = particles();
    double sum = 0.0;
    for (Index i = 0; i < p.size(); ++i) {
        sum += p.is_wall(i) ? 0.0 : p.mass[i];
    }
    return sum;
}

void SphModel::exchange_particles(double t, double dt) {
    // A phase that ends on a time or on the settle watch does so before the removals, so a
    // wall due at its successor's start leaves with this step (as remove_at = "settled"); one
    // that ends on the mass the sinks took can only after them, and its walls follow at once.
    phases_->advance(t + dt);
    remove_departed(t + dt);
    if (phases_->advance(t + dt)) {
        remove_departed(t + dt);
    }
    create_arrivals(t, dt);
}

void SphModel::remove_departed(double time) {
    if (!removals_) {
        return;
    }
    const ParticleSet& p = solver_->particles();
    std::vector<char> gone(static_cast<std::size_t>(p.size()), 0);
    const Index count = parts_.collect_departures(p.view(), time, gone);
    if (count > 0) {
        apply_removal(gone);
    }
}

void SphModel::apply_removal(std::span<const char> gone) {
    std::vector<Index> new_index(gone.size(), -1);
    Index kept = 0;
    for (std::size_t i = 0; i < gone.size(); ++i) {
        if (!gone[i]) {
            new_index[i] = kept++;
        }
    }
    solver_->remove_particles(gone);
    particles::compact(initial_position_, gone);
    particles::compact(initial_velocity_, gone);
    particles::compact(origin_, gone);
    parts_.after_removal(new_index);
}

void SphModel::read_removals(std::istream& in) {
    std::vector<Index> kept;
    io::read_array(in, kept);
    const auto n = static_cast<std::size_t>(particles().size());
    if (kept.size() == n) {
        return;
    }
    // The checkpoint's particles are a subset of the case's, in order: flag the others.
    const std::string other = "checkpoint holds " + std::to_string(kept.size()) +
                              " particles, the case makes " + std::to_string(n);
    if (!removals_) {
        throw std::runtime_error(other + " and has no sink or remove_at to lose any by");
    }
    std::vector<char> gone(n, 1);
    Index previous = -1;
    for (const Index k : kept) {
        if (k <= previous || k >= static_cast<Index>(n)) {
            throw std::runtime_error(other + ", not a subset of them in order");
        }
        gone[static_cast<std::size_t>(k)] = 0;
        previous = k;
    }
    apply_removal(gone);
}

} // namespace grainload::sph
