#include "dem/grain_motion.hpp"

#include <cmath>

namespace grainload::dem {

Vec3 spin_of(const Eigen::Quaterniond& turned, const Vec3& moments, const Vec3& momentum) {
    const Vec3 own = turned.conjugate() * momentum;
    return turned * Vec3(own.cwiseQuotient(moments));
}

Vec3 momentum_of(const Eigen::Quaterniond& turned, const Vec3& moments, const Vec3& spin) {
    const Vec3 own = turned.conjugate() * spin;
    return turned * Vec3(own.cwiseProduct(moments));
}

Eigen::Quaterniond rotated(const Eigen::Quaterniond& turned, const Vec3& turn) {
    // A step's turn is small (omega dt ~ 1e-3 rad): below 1e-3 rad the series cos(a/2) = 1 -
    // a^2/8 + a^4/384 and sin(a/2)/a = 1/2 - a^2/48 + a^4/3840 are exact to the last bit (the
    // next terms are below 1e-19), and cost no sine.
    const double squared = turn.squaredNorm();
    if (!(squared > 0.0)) {
        return turned;
    }
    double cosine = 0.0;
    double sine_over_angle = 0.0;
    if (squared < 1e-6) {
        cosine = 1.0 - squared / 8.0 + squared * squared / 384.0;
        sine_over_angle = 0.5 - squared / 48.0 + squared * squared / 3840.0;
    } else {
        const double angle = std::sqrt(squared);
        cosine = std::cos(0.5 * angle);
        sine_over_angle = std::sin(0.5 * angle) / angle;
    }
    const Vec3 axis = sine_over_angle * turn;
    return (Eigen::Quaterniond(cosine, axis.x(), axis.y(), axis.z()) * turned).normalized();
}

} // namespace grainload::dem
