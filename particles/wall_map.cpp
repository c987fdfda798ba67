// WallMapSet: binning the walls' loads and keeping their interval and window sums, and the scene
// part that drives it. Reading the tables is in wall_map_reader.cpp; the files it writes in
// wall_map_output.cpp.
#include "particles/wall_map.hpp"

#include "io/binary_stream.hpp"
#include "io/output_streams.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace grainload::particles {

double WallMapSet::Map::cell_area() const {
    if (cylinder) {
        return radius * (angle_end - angle_start) / bins_2 * length / bins_1;
    }
    // Plane strain: the edge by 1 m of depth, as the particles' masses are per metre.
    const double area = edge_v.squaredNorm() > 0.0 ? edge_u.cross(edge_v).norm() : edge_u.norm();
    return area / (bins_1 * bins_2);
}

std::optional<std::array<double, 2>> WallMapSet::Map::coordinates(const Vec3& x) const {
    const Vec3 d = x - origin;
    double a = 0.0;
    double b = 0.0;
    if (cylinder) {
        const double along = d.dot(axis);
        const Vec3 radial = d - along * axis;
        if (std::abs(radial.norm() - radius) > reach) {
            return std::nullopt;
        }
        double angle = std::atan2(radial.dot(axis.cross(reference)), radial.dot(reference));
        // The arc may start anywhere: measure the angle from its start, in [0, 2 pi).
        angle = std::fmod(angle - angle_start, 2.0 * std::numbers::pi);
        if (angle < 0.0) {
            angle += 2.0 * std::numbers::pi;
        }
        // Off a partial arc: nearer its start (a negative angle) or its end.
        const double arc = angle_end - angle_start;
        if (angle > arc && 2.0 * std::numbers::pi - angle < angle - arc) {
            angle -= 2.0 * std::numbers::pi;
        }
        a = along / length;
        b = angle / arc;
    } else if (edge_v.squaredNorm() > 0.0) {
        // Coordinates on the (possibly skew) grid: the least-squares solution of
        // d = a edge_u + b edge_v, from the 2 x 2 Gram system; the rest is the distance off it.
        const double uu = edge_u.dot(edge_u);
        const double uv = edge_u.dot(edge_v);
        const double vv = edge_v.dot(edge_v);
        const double du = d.dot(edge_u);
        const double dv = d.dot(edge_v);
        const double det = uu * vv - uv * uv;
        a = (du * vv - dv * uv) / det;
        b = (dv * uu - du * uv) / det;
        if ((d - a * edge_u - b * edge_v).norm() > reach) {
            return std::nullopt;
        }
    } else {
        a = d.dot(edge_u) / edge_u.squaredNorm();
        if ((d - a * edge_u).norm() > reach) {
            return std::nullopt;
        }
    }
    return std::array<double, 2>{a, b};
}

std::array<double, 2> WallMapSet::Map::extents() const {
    if (cylinder) {
        return {length, radius * (angle_end - angle_start)};
    }
    // Plane strain: no second direction to spread a particle's patch over.
    return {edge_u.norm(), edge_v.squaredNorm() > 0.0 ? edge_v.norm() : 0.0};
}

bool WallMapSet::Map::periodic() const {
    return cylinder && angle_end - angle_start >= 2.0 * std::numbers::pi * (1.0 - 1e-12);
}

namespace {

/// The cells of one direction that a patch [lo, hi] (grid units: the grid is [0, 1] in n
/// cells) overlaps, each with its overlap over the patch's part inside the grid (periodic: the
/// patch wraps around instead). Returns their count: at most 2 for a patch no wider than a
/// cell, 0 when it misses the grid.
int overlaps(double lo, double hi, int n, bool periodic, std::array<int, 2>& cells,
             std::array<double, 2>& weights) {
    if (lo == hi) {
        // A point: the cell holding it; one on the grid's far edge is the last cell's.
        if (!periodic && !(lo >= 0.0 && lo <= 1.0)) {
            return 0;
        }
        const int c = static_cast<int>(std::floor(lo * n));
        cells[0] = periodic ? ((c % n) + n) % n : std::min(c, n - 1);
        weights[0] = 1.0;
        return 1;
    }
    if (!periodic) {
        lo = std::max(lo, 0.0);
        hi = std::min(hi, 1.0);
    }
    if (!(hi > lo)) {
        return 0;
    }
    const int first = static_cast<int>(std::floor(lo * n));
    const int last = std::min(static_cast<int>(std::floor(hi * n)), first + 1);
    int count = 0;
    for (int c = first; c <= last; ++c) {
        const double overlap =
            std::min(hi, (c + 1.0) / n) - std::max(lo, static_cast<double>(c) / n);
        if (overlap > 0.0 && (periodic || (c >= 0 && c < n))) {
            cells[static_cast<std::size_t>(count)] = periodic ? ((c % n) + n) % n : c;
            weights[static_cast<std::size_t>(count)] = overlap / (hi - lo);
            ++count;
        }
    }
    return count;
}

} // namespace

int WallMapSet::Map::shares(const Vec3& x, double half,
                            std::array<std::pair<int, double>, 4>& out) const {
    const auto at = coordinates(x);
    if (!at) {
        return 0;
    }
    // The particle stands for a patch one spacing wide centred on it: its load goes to the
    // cells the patch overlaps, in proportion, so that a particle on the border of two cells
    // is shared, not given to one (which striped the map of a uniform load). A patch that
    // reaches past the grid's edge gives its whole load to its part inside: a wall that ends
    // at the edge keeps all of its load.
    const auto extent = extents();
    const double h1 = half / extent[0];
    const double h2 = extent[1] > 0.0 ? half / extent[1] : 0.0;
    std::array<int, 2> cells_1{};
    std::array<int, 2> cells_2{};
    std::array<double, 2> weights_1{};
    std::array<double, 2> weights_2{};
    const int n1 = overlaps((*at)[0] - h1, (*at)[0] + h1, bins_1, false, cells_1, weights_1);
    int n2 = 1; // plane strain: one cell across the depth
    weights_2[0] = 1.0;
    if (extent[1] > 0.0) {
        n2 = overlaps((*at)[1] - h2, (*at)[1] + h2, bins_2, periodic(), cells_2, weights_2);
    }
    int count = 0;
    for (int i = 0; i < n1; ++i) {
        for (int j = 0; j < n2; ++j) {
            out[static_cast<std::size_t>(count++)] = {
                cells_1[static_cast<std::size_t>(i)] * bins_2 +
                    cells_2[static_cast<std::size_t>(j)],
                weights_1[static_cast<std::size_t>(i)] * weights_2[static_cast<std::size_t>(j)]};
        }
    }
    return count;
}

WallMapSet::Load WallMapSet::Map::split(const Vec3& x, const Vec3& n, const Vec3& f) const {
    const double normal = f.dot(n);
    const Vec3 tangential = f - normal * n;
    Vec3 first;
    Vec3 second;
    if (cylinder) {
        const Vec3 d = x - origin;
        const Vec3 radial = d - d.dot(axis) * axis;
        first = axis;
        second = radial.norm() > 0.0 ? Vec3(axis.cross(radial).normalized()) : Vec3::Zero();
    } else {
        first = edge_u.normalized();
        second = edge_v.squaredNorm() > 0.0 ? Vec3(edge_v.normalized()) : Vec3::Zero();
    }
    return {-normal, tangential.dot(first), tangential.dot(second)};
}

std::array<double, 2> WallMapSet::Map::centre(int cell) const {
    const double a = (cell / bins_2 + 0.5) / bins_1;
    const double b = (cell % bins_2 + 0.5) / bins_2;
    if (cylinder) {
        return {a * length,
                (angle_start + b * (angle_end - angle_start)) * 180.0 / std::numbers::pi};
    }
    return {a * edge_u.norm(), b * edge_v.norm()};
}

void WallMapSet::reset() {
    for (Map& map : maps_) {
        map.interval.assign(static_cast<std::size_t>(map.cells()), Load{});
        map.window_sum.assign(static_cast<std::size_t>(map.cells()), Load{});
        map.window_max.assign(static_cast<std::size_t>(map.cells()), Load{});
        map.window_seen = false;
    }
}

void WallMapSet::accumulate(double t, double dt, const WallLoads& loads) {
    for (Map& map : maps_) {
        // The part of the step inside the window enters the window's sum.
        const double overlap =
            std::max(0.0, std::min(t + dt, map.window_end) - std::max(t, map.window_start));
        for (std::size_t m = 0; m < map.walls.size(); ++m) {
            loads_.clear();
            loads(map.walls[m], loads_);
            const double half = map.half_spacing[m];
            // Every step: each load's cells and split (an angle and its patch's overlaps) on all
            // threads, then added in the loads' order, so the sums are the serial loop's.
            const auto count = static_cast<Index>(loads_.size());
            shares_.resize(loads_.size());
#pragma omp parallel for schedule(static)
            for (Index q = 0; q < count; ++q) {
                const WallLoad& load = loads_[static_cast<std::size_t>(q)];
                ParticleShares& mine = shares_[static_cast<std::size_t>(q)];
                mine.count = map.shares(load.at, half, mine.cells);
                if (mine.count > 0) {
                    mine.load = map.split(load.at, load.normal, load.force);
                }
            }
            for (const ParticleShares& mine : shares_) {
                for (int s = 0; s < mine.count; ++s) {
                    const auto [cell, weight] = mine.cells[static_cast<std::size_t>(s)];
                    Load& interval = map.interval[static_cast<std::size_t>(cell)];
                    Load& window = map.window_sum[static_cast<std::size_t>(cell)];
                    for (int c = 0; c < 3; ++c) {
                        interval[c] += weight * dt * mine.load[c];
                        window[c] += weight * overlap * mine.load[c];
                    }
                }
            }
        }
    }
}

WallMapSet::Load WallMapSet::window_mean(const Map& map, int cell) const {
    const double elapsed = std::min(last_time_, map.window_end) - map.window_start;
    Load mean{};
    if (elapsed > 0.0) {
        const Load& sum = map.window_sum[static_cast<std::size_t>(cell)];
        for (int c = 0; c < 3; ++c) {
            mean[c] = sum[c] / (elapsed * map.cell_area());
        }
    }
    return mean;
}

void WallMapSet::record(double time, const std::string& directory) {
    if (recorded_any_ && !(time > last_time_)) {
        return; // an instant already recorded (a restart writes its first frame again)
    }
    const double length = recorded_any_ ? time - last_time_ : 0.0;
    for (Map& map : maps_) {
        // An interval that ends inside the window offers its mean to the window's maximum.
        const bool in_window =
            length > 0.0 && time > map.window_start && time <= map.window_end * (1.0 + 1e-12);
        for (int cell = 0; cell < map.cells(); ++cell) {
            Load& interval = map.interval[static_cast<std::size_t>(cell)];
            for (int c = 0; c < 3 && length > 0.0; ++c) {
                interval[c] /= length * map.cell_area();
            }
            if (in_window) {
                Load& top = map.window_max[static_cast<std::size_t>(cell)];
                for (int c = 0; c < 3; ++c) {
                    top[c] = map.window_seen ? std::max(top[c], interval[c]) : interval[c];
                }
            }
        }
        map.window_seen = map.window_seen || in_window;
        write_interval(map, time, length, directory);
        std::fill(map.interval.begin(), map.interval.end(), Load{});
    }
    last_time_ = time;
    recorded_any_ = true;
    for (const Map& map : maps_) {
        write_window(map, directory);
    }
    instants_ += 1.0;
}

std::vector<double> WallMapSet::state() const {
    std::vector<double> out{last_time_, instants_, recorded_any_ ? 1.0 : 0.0};
    for (const Map& map : maps_) {
        out.push_back(map.window_seen ? 1.0 : 0.0);
        for (const auto* loads : {&map.interval, &map.window_sum, &map.window_max}) {
            for (const Load& load : *loads) {
                out.insert(out.end(), load.begin(), load.end());
            }
        }
    }
    return out;
}

void WallMapSet::set_state(const std::vector<double>& state) {
    std::size_t expected = 3;
    for (const Map& map : maps_) {
        expected += 1 + 9 * static_cast<std::size_t>(map.cells());
    }
    if (state.size() != expected) {
        throw std::runtime_error("checkpoint: the wall maps' state has " +
                                 std::to_string(state.size()) + " numbers, expected " +
                                 std::to_string(expected));
    }
    last_time_ = state[0];
    instants_ = state[1];
    recorded_any_ = state[2] != 0.0;
    std::size_t at = 3;
    for (Map& map : maps_) {
        map.window_seen = state[at++] != 0.0;
        for (auto* loads : {&map.interval, &map.window_sum, &map.window_max}) {
            for (Load& load : *loads) {
                for (double& value : load) {
                    value = state[at++];
                }
            }
        }
    }
}

namespace {

class WallMapPart final : public ScenePart {
  public:
    WallMapPart(std::string name, WallMapSet maps, WallLoads loads)
        : name_(std::move(name)), maps_(std::move(maps)), loads_(std::move(loads)) {}
    std::string_view name() const override { return name_; }
    void after_step(double t, double dt) override { maps_.accumulate(t, dt, loads_); }
    void at_output(double time, io::OutputStreams& output) override {
        maps_.record(time, output.directory());
    }
    void append_results(std::vector<io::ResultFigure>& results) const override {
        maps_.append_results(results);
    }
    void write_checkpoint(std::ostream& out) const override { io::write_array(out, maps_.state()); }
    void read_checkpoint(std::istream& in) override {
        std::vector<double> state;
        io::read_array(in, state);
        maps_.set_state(state);
    }

  private:
    std::string name_;
    WallMapSet maps_;
    WallLoads loads_;
};

} // namespace

std::unique_ptr<ScenePart> wall_map_part(std::string name, WallMapSet maps, WallLoads loads) {
    return std::make_unique<WallMapPart>(std::move(name), std::move(maps), std::move(loads));
}

} // namespace grainload::particles
