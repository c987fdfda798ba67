#include "particles/phase_sequence.hpp"

#include "io/case_table.hpp"
#include "io/named_index.hpp"
#include "io/units.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace grainload::particles {

namespace dim = io::dimension;

namespace {

constexpr std::string_view kPrefix = "phase:";
constexpr double kNever = std::numeric_limits<double>::infinity();
// A phase due at a stated time ends with the step whose end reaches it; a step cut to an output
// instant can end an ulp short of it, and an end at an output instant means that instant (the
// tolerance of the driver's end time and of remove_at).
constexpr double kEndTimeTolerance = 1e-12;
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

/// `end` of a phase table: a time, "settled" or "discharged"; anything else is refused here,
/// with the three forms named, rather than as a malformed time.
PhaseSequence::End read_end_kind(const io::CaseTable& table) {
    const std::string text = table.string("end");
    if (text == "settled") {
        return PhaseSequence::End::settled;
    }
    if (text == "discharged") {
        return PhaseSequence::End::discharged;
    }
    std::string error;
    const auto quantity = io::parse_quantity(text, &error);
    if (!quantity || !(quantity->dimension == dim::kTime)) {
        table.fail("end", "expected a time (e.g. \"1.2 s\"), \"settled\" (with "
                          "kinetic_energy_fraction) or \"discharged\" (with discharged_mass), "
                          "got \"" +
                              text + "\"");
    }
    return PhaseSequence::End::time;
}

/// Mass discharged: kg in 3D, kg per metre of depth in plane strain (the particles' masses).
io::Dimension discharged_mass_dimension(int dimension) {
    return dimension == 2 ? io::Dimension{1, -1, 0, 0} : dim::kMass;
}

/// The phase of one table; `previous_end` is the stated end of the phase before when that and
/// every earlier phase end at stated times (+inf otherwise), which a stated end must follow.
PhaseSequence::Phase read_phase(const io::CaseTable& table, double previous_end) {
    PhaseSequence::Phase phase;
    phase.name = table.string("name");
    if (phase.name.empty()) {
        table.fail("name", "expected a non-empty name");
    }
    phase.end = table.has("end") ? read_end_kind(table) : PhaseSequence::End::run;
    using End = PhaseSequence::End;
    if (phase.end == End::time) {
        phase.end_time = table.positive_quantity("end", dim::kTime);
        if (std::isfinite(previous_end) && !(phase.end_time > previous_end)) {
            std::ostringstream message;
            message << "expected an end after the previous phase's end (" << previous_end << " s)";
            table.fail("end", message.str());
        }
    }
    if (phase.end == End::settled) {
        const double fraction = table.number("kinetic_energy_fraction");
        if (!(fraction > 0.0 && fraction < 1.0)) {
            table.fail("kinetic_energy_fraction", "expected a fraction between 0 and 1, e.g. 1e-3");
        }
        phase.watch = SettleWatch(fraction, kNever);
    } else if (table.has("kinetic_energy_fraction")) {
        table.fail("kinetic_energy_fraction", "applies to end = \"settled\" only");
    }
    if (phase.end == End::discharged) {
        phase.discharged_mass = table.positive_quantity(
            "discharged_mass", discharged_mass_dimension(table.spatial_dimension()));
        phase.mass_unit = table.spatial_dimension() == 2 ? "kg/m" : "kg";
    } else if (table.has("discharged_mass")) {
        table.fail("discharged_mass", "applies to end = \"discharged\" only");
    }
    return phase;
}

} // namespace

PhaseSequence::PhaseSequence(const io::CaseTable& root) {
    const auto tables = root.array_of_tables("phase");
    double previous_end = 0.0;
    for (std::size_t k = 0; k < tables.size(); ++k) {
        Phase phase = read_phase(tables[k], previous_end);
        io::refuse_repeated_name(tables[k], phases_, phase.name, "phase", &Phase::name);
        if (phase.end == End::run && k + 1 < tables.size()) {
            tables[k].fail("", "only the last phase may run to the end of the run: expected "
                               "end = a time, \"settled\" or \"discharged\"");
        }
        previous_end = phase.end == End::time ? phase.end_time : kNever;
        phases_.push_back(std::move(phase));
    }
    if (!phases_.empty()) {
        phases_.front().start = 0.0;
        propagate();
    }
}

bool PhaseSequence::ends_on(End end) const {
    return std::any_of(phases_.begin(), phases_.end(),
                       [end](const Phase& phase) { return phase.end == end; });
}

int PhaseSequence::index_of(const io::CaseTable& table, std::string_view key,
                            std::string_view text) const {
    const std::string_view name = text.substr(kPrefix.size());
    std::string known;
    for (std::size_t k = 0; k < phases_.size(); ++k) {
        if (phases_[k].name == name) {
            return static_cast<int>(k);
        }
        known += (known.empty() ? "\"" : ", \"") + phases_[k].name + "\"";
    }
    table.fail(key, "expected phase:NAME with the name of a [[phase]] (" +
                        (known.empty() ? std::string("none defined") : known) + "), got \"" +
                        std::string(text) + "\"");
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
        if (phase.end == End::time && time >= phase.end_time * (1.0 - kEndTimeTolerance)) {
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

bool names_phase(std::string_view text) {
    return text.substr(0, kPrefix.size()) == kPrefix;
}

std::optional<int> read_phase_reference(const io::CaseTable& table, std::string_view key,
                                        const PhaseSequence* phases) {
    const auto text = table.string_if(key);
    if (!text || !names_phase(*text)) {
        return std::nullopt;
    }
    const PhaseSequence none;
    return (phases != nullptr ? *phases : none).index_of(table, key, *text);
}

} // namespace grainload::particles
