#include "sph/gates.hpp"

#include "particles/phase_sequence.hpp"

#include <algorithm>
#include <cmath>

namespace grainload::sph {

bool GateSet::any(const std::vector<Wall>& walls) {
    return std::any_of(walls.begin(), walls.end(), [](const Wall& wall) {
        return std::isfinite(wall.removal_time) || wall.removal_on_settle ||
               wall.removal_phase >= 0;
    });
}

Index GateSet::collect_departures(const particles::ParticleView& particles, double time,
                                  std::vector<char>& gone) {
    (void)particles;
    const bool settled = settle_ && settle_->watch().settled();
    Index count = 0;
    for (const Wall& wall : *walls_) {
        // A wall due at remove_at leaves after the step whose end reaches it.
        if (wall.count > 0 &&
            (particles::reaches(time, wall.removal_time) || (wall.removal_on_settle && settled))) {
            std::fill_n(gone.begin() + wall.first, wall.count, char{1});
            count += wall.count;
        }
    }
    return count;
}

} // namespace grainload::sph
