#include "particles/settle_watch.hpp"

#include "io/binary_stream.hpp"

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace grainload::particles {

bool SettleWatch::record(double time, double kinetic) {
    if (settled()) {
        return false;
    }
    peak_ = std::max(peak_, kinetic);
    if (time >= after_ && peak_ > 0.0 && kinetic < fraction_ * peak_) {
        settle_time_ = time;
        return true;
    }
    return false;
}

void SettleWatch::set_state(const std::vector<double>& state) {
    if (state.size() != 2) {
        throw std::runtime_error("checkpoint: expected 2 settle-watch entries, found " +
                                 std::to_string(state.size()));
    }
    peak_ = state[0];
    settle_time_ = state[1];
}

void SettlePart::after_step(double t, double dt) {
    const double time = t + dt;
    const double kinetic = kinetic_energy_();
    if (watch_.record(time, kinetic)) {
        std::ostringstream event;
        event << "settled at t = " << time << " s: the material's kinetic energy " << kinetic
              << " J is below " << watch_.fraction() << " of its peak " << watch_.peak() << " J";
        events_.push_back(event.str());
    }
}

void SettlePart::take_events(std::vector<std::string>& events) {
    events.insert(events.end(), events_.begin(), events_.end());
    events_.clear();
}

void SettlePart::append_results(std::vector<io::ResultFigure>& results) const {
    append_settle_results(watch_, results);
}

void SettlePart::write_checkpoint(std::ostream& out) const {
    io::write_array(out, watch_.state());
}

void SettlePart::read_checkpoint(std::istream& in) {
    std::vector<double> state;
    io::read_array(in, state);
    watch_.set_state(state);
    events_.clear();
}

void append_settle_results(const SettleWatch& watch, std::vector<io::ResultFigure>& results) {
    // null (NaN) when the scene never settled.
    results.push_back(
        {"settle_time",
         watch.settled() ? watch.settle_time() : std::numeric_limits<double>::quiet_NaN(), "s",
         std::nullopt, ""});
    results.push_back({"settle_peak_kinetic_energy", watch.peak(), "J", std::nullopt, ""});
}

} // namespace grainload::particles
