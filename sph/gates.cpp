#include "sph/gates.hpp"

#include <algorithm>
#include <cmath>

namespace grainload::sph {

namespace {

// A wall due at remove_at leaves after the step whose end reaches it; the end of a step that
// the driver cut to an output instant can fall an ulp short of that instant, and
// remove_at = an output instant means that instant (as the driver's own end tolerance).
constexpr double kRemovalTimeTolerance = 1e-12;

} // namespace

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
        const double due = wall.removal_time * (1.0 - kRemovalTimeTolerance);
        if (wall.count > 0 && (time >= due || (wall.removal_on_settle && settled))) {
            std::fill_n(gone.begin() + wall.first, wall.count, char{1});
            count += wall.count;
        }
    }
    return count;
}

} // namespace grainload::sph
