#include "sph/heap_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace grainload::sph {

HeapMonitor::HeapMonitor(const HeapSettings& settings, const ParticleSet& particles, double spacing,
                         const Vec3& gravity, int dimension)
    : body_(settings.body), rest_(settings.rest_fraction) {
    frame_.origin = settings.origin;
    frame_.up = -gravity.normalized();
    frame_.spacing = spacing;
    frame_.dimension = dimension;
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -std::numeric_limits<double>::infinity();
    for (const Vec3& x : body_positions(particles)) {
        const double s = (x - frame_.origin).dot(frame_.up);
        lowest = std::min(lowest, s);
        highest = std::max(highest, s);
    }
    frame_.floor_level = lowest - 0.5 * spacing;
    initial_height_ = highest - lowest + spacing;
}

std::vector<Vec3> HeapMonitor::body_positions(const ParticleSet& particles) const {
    std::vector<Vec3> x;
    for (Index i = 0; i < particles.size(); ++i) {
        if (particles.body_id[i] == body_ && !particles.is_wall(i)) {
            x.push_back(particles.position[i]);
        }
    }
    return x;
}

std::vector<double> HeapMonitor::body_masses(const ParticleSet& particles) const {
    std::vector<double> m;
    for (Index i = 0; i < particles.size(); ++i) {
        if (particles.body_id[i] == body_ && !particles.is_wall(i)) {
            m.push_back(particles.mass[i]);
        }
    }
    return m;
}

void HeapMonitor::record(double time, const ParticleSet& particles) {
    double energy = 0.0;
    for (Index i = 0; i < particles.size(); ++i) {
        if (particles.body_id[i] == body_ && !particles.is_wall(i)) {
            energy += 0.5 * particles.mass[i] * particles.velocity[i].squaredNorm();
        }
    }
    rest_.add(time, energy);
}

void HeapMonitor::append_results(const ParticleSet& particles,
                                 std::vector<io::ResultFigure>& results) const {
    const HeapMeasures heap =
        measure_heap(body_positions(particles), body_masses(particles), frame_);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double degrees = 180.0 / std::numbers::pi;
    // summary.json writes NaN as null: an angle that cannot be fitted, a rest not reached.
    results.push_back({"heap_initial_height", initial_height_, "m", std::nullopt, ""});
    results.push_back({"heap_final_height", heap.final_height, "m", std::nullopt, ""});
    results.push_back({"heap_axis_height", heap.axis_height, "m", std::nullopt,
                       "the heap's top within one spacing of the axis (2D: of the back face)"});
    results.push_back({"heap_run_out", heap.run_out, "m", std::nullopt, ""});
    results.push_back({"heap_run_out_99", heap.run_out_99, "m", std::nullopt,
                       "distance from the axis (2D: the back face) holding 99 % of the body's "
                       "mass, every particle counted"});
    results.push_back(
        {"heap_angle", heap.angle ? *heap.angle * degrees : nan, "deg", std::nullopt, ""});
    results.push_back(
        {"heap_time_to_rest", rest_.rest_time().value_or(nan), "s", std::nullopt, ""});
    results.push_back({"heap_peak_kinetic_energy", rest_.peak(), "J", std::nullopt, ""});
    results.push_back({"heap_peak_time", rest_.peak_time(), "s", std::nullopt, ""});
    results.push_back({"heap_final_kinetic_energy_ratio",
                       rest_.peak() > 0.0 ? rest_.last() / rest_.peak() : nan, "", std::nullopt,
                       ""});
    results.push_back(
        {"heap_particles", static_cast<double>(heap.heap_count), "", std::nullopt, ""});
    results.push_back(
        {"heap_particles_outside", static_cast<double>(heap.outside_count), "", std::nullopt, ""});
}

} // namespace grainload::sph
