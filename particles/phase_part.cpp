#include "particles/phase_part.hpp"

#include "io/binary_stream.hpp"

namespace grainload::particles {

PhasePart::PhasePart(PhaseSequence phases, Hooks hooks, bool report_settle)
    : phases_(std::move(phases)), hooks_(std::move(hooks)), report_settle_(report_settle) {}

bool PhasePart::advance(double time) {
    if (phases_.empty()) {
        return false;
    }
    const double discharged = hooks_.discharged ? hooks_.discharged() : 0.0;
    std::vector<std::string> ended = phases_.update(time, discharged);
    if (ended.empty()) {
        return false;
    }
    events_.insert(events_.end(), ended.begin(), ended.end());
    apply_starts();
    return true;
}

void PhasePart::apply_starts() const {
    if (hooks_.apply_starts) {
        hooks_.apply_starts(phases_);
    }
}

void PhasePart::after_step(double t, double dt) {
    if (phases_.ends_on(PhaseSequence::End::settled)) {
        phases_.record_kinetic(t + dt, hooks_.kinetic_energy());
    }
}

void PhasePart::append_results(std::vector<io::ResultFigure>& results) const {
    if (!report_settle_) {
        return;
    }
    for (const PhaseSequence::Phase& phase : phases_.phases()) {
        if (phase.end == PhaseSequence::End::settled) {
            // The figures of a standalone settle watch, which a case moved to the phase table
            // keeps.
            append_settle_results(phase.watch, results);
            return;
        }
    }
}

void PhasePart::take_events(std::vector<std::string>& events) {
    events.insert(events.end(), events_.begin(), events_.end());
    events_.clear();
}

void PhasePart::write_checkpoint(std::ostream& out) const {
    io::write_array(out, phases_.state());
}

void PhasePart::read_checkpoint(std::istream& in) {
    events_.clear();
    std::vector<double> state;
    io::read_array(in, state);
    phases_.set_state(state);
    apply_starts();
}

} // namespace grainload::particles
