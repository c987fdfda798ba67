// SphModel's sources: particles entering through [[sph.source]] regions (a scene part), and
// the creation log a checkpoint replays. The rest of SphModel is in sph_model.cpp and
// sph_model_outlets.cpp.
#include "io/binary_stream.hpp"
#include "sph/sph_model.hpp"

#include <stdexcept>

namespace grainload::sph {

namespace {

// Each creation-log entry: position (3), velocity (3), mass, body and material.
constexpr std::size_t kLogEntry = 9;

} // namespace

void SphModel::set_sources(std::shared_ptr<SourceSet> sources) {
    sources_ = std::move(sources);
    if (!sources_->empty()) {
        parts_.add(sources_);
    }
}

void SphModel::create_arrivals(double t, double dt) {
    if (sources_->empty()) {
        return;
    }
    const std::vector<particles::Arrival> arrivals =
        parts_.collect_arrivals(solver_->particles().view(), t, dt);
    if (!arrivals.empty()) {
        apply_creation(arrivals, true);
    }
}

void SphModel::apply_creation(std::span<const particles::Arrival> arrivals, bool book_energy) {
    std::vector<SphSolver::NewParticle> added;
    for (const particles::Arrival& a : arrivals) {
        added.push_back({a.position, a.velocity, a.mass, a.body, a.material});
        const auto serial = static_cast<Index>(created_log_.size() / kLogEntry);
        origin_.push_back(built_count_ + serial);
        initial_position_.push_back(a.position);
        initial_velocity_.push_back(a.velocity);
        created_log_.insert(created_log_.end(),
                            {a.position.x(), a.position.y(), a.position.z(), a.velocity.x(),
                             a.velocity.y(), a.velocity.z(), a.mass, static_cast<double>(a.body),
                             static_cast<double>(a.material)});
    }
    solver_->add_particles(added, book_energy);
}

void SphModel::write_created(std::ostream& out) const {
    if (!sources_->empty()) {
        io::write_array(out, created_log_);
    }
}

void SphModel::read_created(std::istream& in) {
    if (sources_->empty()) {
        return;
    }
    std::vector<double> log;
    io::read_array(in, log);
    if (log.size() % kLogEntry != 0) {
        throw std::runtime_error("checkpoint: the creation log is not whole entries");
    }
    // The created particles in creation order, after the case's: the removals that follow
    // (read_removals) then name them by original index like the case's own.
    if (log == created_log_) {
        return; // a live scene going back to a state with the same particles (a coupling pass)
    }
    if (!created_log_.empty()) {
        throw std::runtime_error("checkpoint: the scene has created other particles than the "
                                 "checkpoint's; only a freshly built scene can read it");
    }
    std::vector<particles::Arrival> arrivals;
    for (std::size_t k = 0; k < log.size(); k += kLogEntry) {
        const double body = log[k + 7];
        const double material = log[k + 8];
        if (!(body >= 0.0 && body < static_cast<double>(body_names_.size()) && material >= 0.0 &&
              material < static_cast<double>(materials_->size()) && log[k + 6] > 0.0)) {
            throw std::runtime_error("checkpoint: a created particle names no body or material "
                                     "of the case, or has no mass");
        }
        arrivals.push_back({Vec3(log[k], log[k + 1], log[k + 2]),
                            Vec3(log[k + 3], log[k + 4], log[k + 5]), log[k + 6],
                            static_cast<int>(body), static_cast<int>(material)});
    }
    if (!arrivals.empty()) {
        apply_creation(arrivals, false);
    }
}

} // namespace grainload::sph
