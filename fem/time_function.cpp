#include "fem/time_function.hpp"

#include <stdexcept>

namespace grainload::fem {

TimeFunction::TimeFunction(std::vector<std::pair<double, double>> points)
    : points_(std::move(points)) {
    if (points_.empty()) {
        throw std::invalid_argument("a time function needs at least one point");
    }
    for (std::size_t i = 1; i < points_.size(); ++i) {
        if (!(points_[i].first > points_[i - 1].first)) {
            throw std::invalid_argument("time function points must have increasing times");
        }
    }
}

double TimeFunction::operator()(double t) const {
    if (t <= points_.front().first) {
        return points_.front().second;
    }
    for (std::size_t i = 1; i < points_.size(); ++i) {
        const auto& [t1, f1] = points_[i];
        if (t <= t1) {
            const auto& [t0, f0] = points_[i - 1];
            return f0 + (f1 - f0) * (t - t0) / (t1 - t0);
        }
    }
    return points_.back().second;
}

} // namespace grainload::fem
