#include "sph/escape_watch.hpp"

#include "particles/point_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace grainload::sph {

namespace {

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
    const particles::PointBounds box =
        particles::point_bounds(particles.position, [](Index) { return true; });
    for (Index i = 0; i < particles.size(); ++i) {
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

EscapeWatch::Reach EscapeWatch::reach_now(const ParticleSet& particles) const {
    // Walls where they are now widen the box by the same margin (their own extent at the start
    // is in it already) and lend their speed to v0. Checked every step, so reduced over the
    // threads (maxima are exact in any order).
    const Index n = particles.size();
    const particles::PointBounds walls = particles::point_bounds(
        particles.position, [&particles](Index i) { return particles.is_wall(i); });
    double v0 = initial_speed_;
#pragma omp parallel for schedule(static) reduction(max : v0)
    for (Index i = 0; i < n; ++i) {
        if (particles.is_wall(i)) {
            v0 = std::max(v0, particles.velocity[i].norm());
        }
    }
    Reach reach{lower_, upper_, 0.0, v0};
    if (!walls.empty()) {
        reach.lower = reach.lower.cwiseMin(walls.lower - Vec3::Constant(margin_));
        reach.upper = reach.upper.cwiseMax(walls.upper + Vec3::Constant(margin_));
    }
    for (int a = 0; a < dimension_; ++a) {
        reach.height = std::max(reach.height, reach.upper[a] - reach.lower[a]);
    }
    return reach;
}

std::optional<std::string>
EscapeWatch::check(const ParticleSet& particles,
                   const std::function<std::string(int body_id)>& body_name) const {
    if (!active_) {
        return std::nullopt;
    }
    const Index n = particles.size();
    const Reach reach = reach_now(particles);
    const Vec3& lower = reach.lower;
    const Vec3& upper = reach.upper;
    const double height = reach.height;
    const double v0 = reach.v0;
    // How far particle i lies outside the box, and how fast it leaves it (0, 0 inside).
    auto outside_of = [&](Index i, double& outward) {
        const Vec3& x = particles.position[i];
        Vec3 outside = Vec3::Zero();
        for (int a = 0; a < dimension_; ++a) {
            outside[a] = x[a] - std::clamp(x[a], lower[a], upper[a]);
        }
        const double distance = outside.norm();
        outward = distance > 0.0 ? particles.velocity[i].dot(outside / distance) : 0.0;
        return distance;
    };
    auto limit_at = [&](double distance) {
        return kEscapeSpeedFactor * std::sqrt(v0 * v0 + 2.0 * gravity_ * (height + distance));
    };
    // The lowest escaping index, as the serial scan would name it.
    Index first = n;
#pragma omp parallel for schedule(static) reduction(min : first)
    for (Index i = 0; i < n; ++i) {
        double outward = 0.0;
        const double distance = particles.is_wall(i) ? 0.0 : outside_of(i, outward);
        if (distance > 0.0 && outward > limit_at(distance)) {
            first = std::min(first, i);
        }
    }
    if (first < n) {
        double outward = 0.0;
        const double distance = outside_of(first, outward);
        const Vec3& x = particles.position[first];
        std::ostringstream out;
        out << "particle " << first << " (body " << body_name(particles.body_id[first])
            << ") escaped the scene: at " << vector_text(x, dimension_) << " m, " << distance
            << " m outside the scene box " << vector_text(lower, dimension_) << " to "
            << vector_text(upper, dimension_) << " m, moving outward at " << outward
            << " m/s, faster than the " << limit_at(distance)
            << " m/s a fall from the top of the scene could give it (2 sqrt(v0^2 + 2 g (H + "
               "d)), v0 = "
            << v0 << " m/s, H = " << height << " m)";
        return out.str();
    }
    return std::nullopt;
}

} // namespace grainload::sph
