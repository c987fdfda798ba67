#include "particles/phase_sequence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace grainload::particles {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
// The checkpoint's entries per phase: start, finish, discharged at start, watch peak and time.
constexpr std::size_t kStateEntries = 5;

const char* end_label(PhaseSequence::End end) {
    switch (end) {
    case PhaseSequence::End::time:
        return "time";
    case PhaseSequence::End::settled:
        return "settled";
    case PhaseSequence::End::discharged:
        return "discharged";
    case PhaseSequence::End::run:
        break;
    }
    return "";
}

} // namespace

PhaseSequence::PhaseSequence(std::vector<Phase> phases) : phases_(std::move(phases)) {
    if (!phases_.empty()) {
        phases_.front().start = 0.0;
        propagate();
    }
}

bool PhaseSequence::ends_on(End end) const {
    return std::any_of(phases_.begin(), phases_.end(),
                       [end](const Phase& phase) { return phase.end == end; });
}

void PhaseSequence::propagate() {
    for (std::size_t k = current_; k + 1 < phases_.size(); ++k) {
        const Phase& phase = phases_[k];
        if (phase.end != End::time || !std::isfinite(phase.start)) {
            break;
        }
        // A stated end already passed when the phase began (a condition before it ended late)
        // ends the phase as it begins.
        phases_[k + 1].start = std::max(phase.end_time, phase.start);
    }
    for (Phase& phase : phases_) {
        if (phase.end == End::settled) {
            phase.watch.set_after(phase.start);
        }
    }
}

void PhaseSequence::record_kinetic(double time, double kinetic) {
    for (std::size_t k = current_; k < phases_.size(); ++k) {
        if (phases_[k].end == End::settled) {
            phases_[k].watch.record(time, kinetic);
        }
    }
}

std::string PhaseSequence::end_reason(const Phase& phase, double discharged) const {
    std::ostringstream reason;
    switch (phase.end) {
    case End::time:
        reason << "its end time " << phase.end_time << " s";
        break;
    case End::settled:
        reason << "settled: the material's kinetic energy below " << phase.watch.fraction()
               << " of its peak " << phase.watch.peak() << " J";
        break;
    case End::discharged:
        reason << "discharged: " << discharged - phase.discharged_at_start << ' ' << phase.mass_unit
               << " through the sinks since it began";
        break;
    case End::run:
        break;
    }
    return reason.str();
}

std::vector<std::string> PhaseSequence::update(double time, double discharged) {
    std::vector<std::string> events;
    while (current_ < phases_.size()) {
        Phase& phase = phases_[current_];
        double finish = kNever;
        if (phase.end == End::time && reaches(time, phase.end_time)) {
            finish = std::max(phase.end_time, phase.start);
        } else if (phase.end == End::settled && phase.watch.settled()) {
            finish = phase.watch.settle_time();
        } else if (phase.end == End::discharged &&
                   discharged - phase.discharged_at_start >= phase.discharged_mass) {
            finish = time;
        }
        if (!std::isfinite(finish)) {
            break;
        }
        phase.finish = finish;
        std::ostringstream line;
        line.precision(9);
        line << "phase \"" << phase.name << "\" ended at t = " << finish << " s ("
             << end_reason(phase, discharged) << ")";
        ++current_;
        if (current_ < phases_.size()) {
            Phase& next = phases_[current_];
            next.start = finish;
            next.discharged_at_start = discharged;
            propagate();
            line << "; phase \"" << next.name << "\" begins";
        }
        events.push_back(line.str());
    }
    return events;
}

void PhaseSequence::append_records(std::vector<io::PhaseRecord>& records) const {
    const double none = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t k = 0; k < phases_.size(); ++k) {
        const Phase& phase = phases_[k];
        const bool ended = k < current_;
        records.push_back({phase.name, k <= current_ ? phase.start : none,
                           ended ? phase.finish : none, ended ? end_label(phase.end) : ""});
    }
}

std::vector<double> PhaseSequence::state() const {
    std::vector<double> state{static_cast<double>(current_)};
    for (const Phase& phase : phases_) {
        const auto watch = phase.watch.state();
        state.insert(state.end(),
                     {phase.start, phase.finish, phase.discharged_at_start, watch[0], watch[1]});
    }
    return state;
}

void PhaseSequence::set_state(const std::vector<double>& state) {
    if (state.size() != 1 + kStateEntries * phases_.size() || !(state[0] >= 0.0) ||
        state[0] > static_cast<double>(phases_.size())) {
        throw std::runtime_error("checkpoint: the phase state does not match the case's " +
                                 std::to_string(phases_.size()) + " phases");
    }
    current_ = static_cast<std::size_t>(state[0]);
    for (std::size_t k = 0; k < phases_.size(); ++k) {
        const double* entry = state.data() + 1 + kStateEntries * k;
        Phase& phase = phases_[k];
        phase.start = entry[0];
        phase.finish = entry[1];
        phase.discharged_at_start = entry[2];
        phase.watch.set_state({entry[3], entry[4]});
        phase.watch.set_after(phase.start);
    }
}

} // namespace grainload::particles
