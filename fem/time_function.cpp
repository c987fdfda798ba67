#include "fem/time_function.hpp"

#include "io/case_table.hpp"

#include <stdexcept>

namespace grainload::fem {

namespace dim = io::dimension;

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

std::map<std::string, TimeFunction> read_time_functions(const io::CaseTable& fem) {
    std::map<std::string, TimeFunction> functions;
    for (const io::CaseTable& table : fem.array_of_tables("time_function")) {
        const std::string name = table.string("name");
        if (functions.count(name) != 0) {
            table.fail("name", "time function '" + name + "' is defined twice");
        }
        const std::string type = table.choice_or("type", {"points", "ramp"}, "points");
        try {
            functions.emplace(
                name, type == "ramp"
                          ? TimeFunction::ramp(table.positive_quantity("ramp_time", dim::kTime))
                          : TimeFunction(table.quantity_pairs("points", dim::kTime, dim::kNone)));
        } catch (const std::invalid_argument& e) {
            table.fail("points", e.what());
        }
    }
    return functions;
}

} // namespace grainload::fem
