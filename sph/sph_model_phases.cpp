// SphModel's phases ([[phase]]): the settle watches that see the material's kinetic energy, the
// phases' ends after each step, and their starts handed to the walls and sources that name
// them. The rest of SphModel is in sph_model.cpp.
#include "sph/sph_model.hpp"

#include <limits>
#include <sstream>

namespace grainload::sph {

void SphModel::record_kinetic_energy(double time) {
    if (phases_.ends_on(particles::PhaseSequence::End::settled)) {
        phases_.record_kinetic(time, solver_->kinetic_energy());
    }
}

bool SphModel::advance_phases(double time) {
    if (phases_.empty()) {
        return false;
    }
    std::vector<std::string> ended = phases_.update(time, sinks_->discharged());
    if (ended.empty()) {
        return false;
    }
    events_.insert(events_.end(), ended.begin(), ended.end());
    apply_phase_starts();
    return true;
}

void SphModel::apply_phase_starts() {
    if (phases_.empty()) {
        return;
    }
    for (Wall& wall : solver_->walls()) {
        if (wall.removal_phase >= 0) {
            wall.removal_time = phases_.start(wall.removal_phase);
        }
        auto* motion = dynamic_cast<RigidMotion*>(wall.driver.get());
        if (motion != nullptr && motion->history_phase >= 0) {
            motion->start_histories(phases_.start(motion->history_phase));
        }
    }
    sources_->apply_phase_starts(phases_);
}

void SphModel::append_phases(std::vector<io::PhaseRecord>& records) const {
    phases_.append_records(records);
}

void SphModel::append_phase_results(std::vector<io::ResultFigure>& results) const {
    for (const particles::PhaseSequence::Phase& phase : phases_.phases()) {
        if (phase.end != particles::PhaseSequence::End::settled) {
            continue;
        }
        // The figures of [sph.settle], which a case moved to the phase table keeps.
        particles::append_settle_results(phase.watch, results);
        return;
    }
}

} // namespace grainload::sph
