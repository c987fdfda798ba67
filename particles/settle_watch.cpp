#include "particles/settle_watch.hpp"

#include "io/case_table.hpp"

#include <algorithm>
#include <stdexcept>

namespace grainload::particles {

SettleWatch::SettleWatch(const io::CaseTable& settle)
    : fraction_(settle.number("kinetic_energy_fraction")),
      after_(settle.quantity_or("after", io::dimension::kTime, 0.0)) {
    if (!(fraction_ > 0.0 && fraction_ < 1.0)) {
        settle.fail("kinetic_energy_fraction", "expected a fraction between 0 and 1, e.g. 1e-3");
    }
    if (!(after_ >= 0.0)) {
        settle.fail("after", "expected a time >= 0 s");
    }
}

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

} // namespace grainload::particles
