#include "sph/escape_watch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace grainload::sph {

namespace {

struct Box {
    Vec3 lower = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 upper = Vec3::Constant(-std::numeric_limits<double>::infinity());
    void add(const Vec3& x) {
        lower = lower.cwiseMin(x);
        upper = upper.cwiseMax(x);
    }
    bool empty() const { return !(lower.x() <= upper.x()); }
};

std::string vector_text(const Vec3& v, int dimension) {
    std::ostringstream out;
    out << '(' << v.x() << ", " << v.y();
    if (dimension == 3) {
        out << ", " << v.z();
    }
    out << ')';
    return out.str();
}

} // namespace

EscapeWatch::EscapeWatch(const ParticleSet& particles, const Vec3& gravity, int dimension)
    : dimension_(dimension), gravity_(gravity.norm()) {
    Box box;
    for (Index i = 0; i < particles.size(); ++i) {
        box.add(particles.position[i]);
        initial_speed_ = std::max(initial_speed_, particles.velocity[i].norm());
    }
    if (box.empty() || !box.lower.allFinite() || !box.upper.allFinite()) {
        return;
    }
    double extent = 0.0;
    for (int a = 0; a < dimension; ++a) {
        extent = std::max(extent, box.upper[a] - box.lower[a]);
    }
    margin_ = kEscapeMarginFraction * extent;
    lower_ = box.lower - Vec3::Constant(margin_);
    upper_ = box.upper + Vec3::Constant(margin_);
    active_ = extent > 0.0;
}

std::optional<std::string>
EscapeWatch::check(const ParticleSet& particles,
                   const std::function<std::string(int body_id)>& body_name) const {
    if (!active_) {
        return std::nullopt;
    }
    // Walls where they are now widen the box by the same margin (their own extent at the start
    // is in it already) and lend their speed to v0.
    Box walls;
    double v0 = initial_speed_;
    for (Index i = 0; i < particles.size(); ++i) {
        if (particles.is_wall(i)) {
            walls.add(particles.position[i]);
            v0 = std::max(v0, particles.velocity[i].norm());
        }
    }
    Vec3 lower = lower_;
    Vec3 upper = upper_;
    if (!walls.empty()) {
        lower = lower.cwiseMin(walls.lower - Vec3::Constant(margin_));
        upper = upper.cwiseMax(walls.upper + Vec3::Constant(margin_));
    }
    double height = 0.0;
    for (int a = 0; a < dimension_; ++a) {
        height = std::max(height, upper[a] - lower[a]);
    }
    for (Index i = 0; i < particles.size(); ++i) {
        if (particles.is_wall(i)) {
            continue;
        }
        const Vec3& x = particles.position[i];
        Vec3 outside = Vec3::Zero();
        for (int a = 0; a < dimension_; ++a) {
            outside[a] = x[a] - std::clamp(x[a], lower[a], upper[a]);
        }
        const double distance = outside.norm();
        if (!(distance > 0.0)) {
            continue;
        }
        const double outward = particles.velocity[i].dot(outside / distance);
        const double limit =
            kEscapeSpeedFactor * std::sqrt(v0 * v0 + 2.0 * gravity_ * (height + distance));
        if (outward > limit) {
            std::ostringstream out;
            out << "particle " << i << " (body " << body_name(particles.body_id[i])
                << ") escaped the scene: at " << vector_text(x, dimension_) << " m, " << distance
                << " m outside the scene box " << vector_text(lower, dimension_) << " to "
                << vector_text(upper, dimension_) << " m, moving outward at " << outward
                << " m/s, faster than the " << limit
                << " m/s a fall from the top of the scene could give it (2 sqrt(v0^2 + 2 g (H + "
                   "d)), v0 = "
                << v0 << " m/s, H = " << height << " m)";
            return out.str();
        }
    }
    return std::nullopt;
}

} // namespace grainload::sph
