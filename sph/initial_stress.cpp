#include "sph/initial_stress.hpp"

#include "sph/rates.hpp"

#include <algorithm>
#include <limits>

namespace grainload::sph {

void set_geostatic_stress(ParticleSet& p, Index first, const Vec3& gravity, double spacing,
                          double lateral_ratio) {
    const double g = gravity.norm();
    const Vec3 up = -gravity / g;
    double top = -std::numeric_limits<double>::infinity();
    for (Index i = first; i < p.size(); ++i) {
        top = std::max(top, p.position[i].dot(up) + 0.5 * spacing);
    }
    for (Index i = first; i < p.size(); ++i) {
        const double vertical = -p.density[i] * g * (top - p.position[i].dot(up));
        const Mat3 sigma = lateral_ratio * vertical * Mat3::Identity() +
                           (1.0 - lateral_ratio) * vertical * up * up.transpose();
        p.stress[i] = stress_voigt(sigma);
    }
}

} // namespace grainload::sph
