// SphModel's phases ([[phase]]): the part that holds them, reading the solver's kinetic energy
// and the sinks' discharged mass, and their starts handed to the walls and sources that name
// them. The rest of SphModel is in sph_model.cpp.
#include "sph/sph_model.hpp"

namespace grainload::sph {

void SphModel::set_phases(particles::PhaseSequence phases, bool report_settle) {
    particles::PhasePart::Hooks hooks{
        [this] { return solver_->kinetic_energy(); }, [this] { return sinks_->discharged(); },
        [this](const particles::PhaseSequence& sequence) { apply_phase_starts(sequence); }};
    phases_ =
        std::make_shared<particles::PhasePart>(std::move(phases), std::move(hooks), report_settle);
}

void SphModel::apply_phase_starts(const particles::PhaseSequence& phases) {
    if (phases.empty() || !solver_) {
        return;
    }
    for (Wall& wall : solver_->walls()) {
        if (wall.removal_phase >= 0) {
            wall.removal_time = phases.start(wall.removal_phase);
        }
        auto* motion = dynamic_cast<RigidMotion*>(wall.driver.get());
        if (motion != nullptr && motion->history_phase >= 0) {
            motion->start_histories(phases.start(motion->history_phase));
        }
    }
    sources_->apply_phase_starts(phases);
}

void SphModel::append_phases(std::vector<io::PhaseRecord>& records) const {
    phases_->sequence().append_records(records);
}

} // namespace grainload::sph
