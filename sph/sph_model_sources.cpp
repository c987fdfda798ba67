// SphModel's sources: particles entering through [[sph.source]] regions, and the creation log
// a checkpoint replays. The rest of SphModel is in sph_model.cpp and sph_model_outlets.cpp.
#include "io/binary_stream.hpp"
#include "io/case_table.hpp"
#include "sph/sph_model.hpp"

#include <stdexcept>

namespace grainload::sph {

namespace {

// Each creation-log entry: the source's index and the position the particle was created at.
constexpr std::size_t kLogEntry = 4;

} // namespace

void SphModel::build_sources(const io::CaseTable& sph) {
    std::vector<double> density;
    for (const int material : body_material_) {
        density.push_back((*materials_)[material].density());
    }
    sources_ = SourceSet(sph, body_names_, body_material_, density, spacing_, dimension_, gravity_,
                         &phases_);
}

void SphModel::create_arrivals(double t, double dt) {
    if (sources_.empty()) {
        return;
    }
    const std::vector<Arrival> arrivals = sources_.collect(solver_->particles(), t, dt);
    if (!arrivals.empty()) {
        apply_creation(arrivals, true);
    }
}

void SphModel::apply_creation(std::span<const Arrival> arrivals, bool book_energy) {
    std::vector<SphSolver::NewParticle> added;
    for (const Arrival& a : arrivals) {
        const auto& source = sources_.sources()[static_cast<std::size_t>(a.source)];
        added.push_back(
            {a.position, a.velocity, source.particle_mass, source.body, source.material});
        const auto serial = static_cast<Index>(created_log_.size() / kLogEntry);
        origin_.push_back(built_count_ + serial);
        initial_position_.push_back(a.position);
        initial_velocity_.push_back(a.velocity);
        created_log_.insert(created_log_.end(), {static_cast<double>(a.source), a.position.x(),
                                                 a.position.y(), a.position.z()});
    }
    solver_->add_particles(added, book_energy);
}

void SphModel::write_created(std::ostream& out) const {
    if (!sources_.empty()) {
        io::write_array(out, created_log_);
    }
}

void SphModel::read_created(std::istream& in) {
    if (sources_.empty()) {
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
    std::vector<Arrival> arrivals;
    for (std::size_t k = 0; k < log.size(); k += kLogEntry) {
        const auto source = static_cast<int>(log[k]);
        if (source < 0 || source >= static_cast<int>(sources_.sources().size())) {
            throw std::runtime_error("checkpoint: a created particle names no source of the case");
        }
        arrivals.push_back({Vec3(log[k + 1], log[k + 2], log[k + 3]),
                            sources_.sources()[static_cast<std::size_t>(source)].velocity, source});
    }
    if (!arrivals.empty()) {
        apply_creation(arrivals, false);
    }
}

} // namespace grainload::sph
