#include "sph/heap_measures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <utility>

namespace grainload::sph {

namespace {

/// Union-find with path halving: the clusters of a contact graph in near-linear time.
struct DisjointSets {
    explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    std::size_t find(std::size_t i) {
        while (parent[i] != i) {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        return i;
    }
    void join(std::size_t a, std::size_t b) {
        a = find(a);
        b = find(b);
        if (a != b) {
            parent[std::max(a, b)] = std::min(a, b); // the root is the lowest index
        }
    }
    std::vector<std::size_t> parent;
};

std::int64_t cell_key(std::int64_t i, std::int64_t j, std::int64_t k) {
    // 21 bits per axis: particles of one body stay far within 2^20 cells of each other.
    constexpr std::int64_t kMask = (std::int64_t{1} << 21) - 1;
    return ((i & kMask) << 42) | ((j & kMask) << 21) | (k & kMask);
}

/// Horizontal coordinate of a point relative to the origin: its distance from the vertical
/// axis (3D) or its distance in front of the back face along the in-plane horizontal (2D).
double horizontal(const Vec3& d, const HeapFrame& frame) {
    if (frame.dimension == 2) {
        const Vec3 forward(frame.up.y(), -frame.up.x(), 0.0); // up turned by -90 deg about z
        return d.dot(forward);
    }
    return (d - d.dot(frame.up) * frame.up).norm();
}

/// Share of the body's mass inside the mass-based run-out: the toe's last per cent, whose
/// grains a cluster may or may not reach, is left out, so the figure moves with the deposit
/// instead of jumping when a few particles part from the heap.
constexpr double kRunOutMassShare = 0.99;

/// The smallest distance from the axis (3D) or back face (2D) such that the particles whose
/// far edge (centre + dp/2) lies within it hold kRunOutMassShare of the total mass.
double mass_run_out(const std::vector<Vec3>& position, const std::vector<double>& mass,
                    const HeapFrame& frame) {
    std::vector<std::pair<double, double>> edges; // (far edge, mass)
    double total = 0.0;
    for (std::size_t i = 0; i < position.size(); ++i) {
        edges.emplace_back(horizontal(position[i] - frame.origin, frame) + 0.5 * frame.spacing,
                           mass[i]);
        total += mass[i];
    }
    std::sort(edges.begin(), edges.end());
    double held = 0.0;
    for (const auto& [edge, m] : edges) {
        held += m;
        if (held >= kRunOutMassShare * total) {
            return edge;
        }
    }
    return edges.empty() ? 0.0 : edges.back().first;
}

/// The heap's surface in one bin of its horizontal coordinate: the highest top there.
struct SurfaceSample {
    double coordinate = 0.0;
    double top = -std::numeric_limits<double>::infinity();
};

/// Least-squares line top = a + b c through the samples between 20 % and 80 % of the heap's
/// height `top`: the cone's flank, without the rounded apex and the thin toe of the heap. Its
/// angle (rad); none with fewer than three samples on the flank.
std::optional<double> flank_angle(const std::vector<SurfaceSample>& bins, double top) {
    double n = 0.0, sc = 0.0, st = 0.0, scc = 0.0, sct = 0.0;
    for (const SurfaceSample& s : bins) {
        if (s.top >= 0.2 * top && s.top <= 0.8 * top) {
            n += 1.0;
            sc += s.coordinate;
            st += s.top;
            scc += s.coordinate * s.coordinate;
            sct += s.coordinate * s.top;
        }
    }
    const double spread = n * scc - sc * sc;
    if (n >= 3.0 && spread > 0.0) {
        return std::atan(-(n * sct - sc * st) / spread);
    }
    return std::nullopt;
}

} // namespace

std::vector<char> largest_cluster(const std::vector<Vec3>& position, double link_distance) {
    const std::size_t n = position.size();
    std::vector<char> member(n, 0);
    if (n == 0) {
        return member;
    }
    // Cells of side link_distance: linked particles lie in the same or adjacent cells.
    auto cell_of = [&](const Vec3& x) {
        return std::array<std::int64_t, 3>{
            static_cast<std::int64_t>(std::floor(x.x() / link_distance)),
            static_cast<std::int64_t>(std::floor(x.y() / link_distance)),
            static_cast<std::int64_t>(std::floor(x.z() / link_distance))};
    };
    std::unordered_map<std::int64_t, std::vector<std::size_t>> cells;
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = cell_of(position[i]);
        cells[cell_key(c[0], c[1], c[2])].push_back(i);
    }
    DisjointSets sets(n);
    const double limit2 = link_distance * link_distance;
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = cell_of(position[i]);
        for (std::int64_t di = -1; di <= 1; ++di) {
            for (std::int64_t dj = -1; dj <= 1; ++dj) {
                for (std::int64_t dk = -1; dk <= 1; ++dk) {
                    const auto found = cells.find(cell_key(c[0] + di, c[1] + dj, c[2] + dk));
                    if (found == cells.end()) {
                        continue;
                    }
                    for (std::size_t j : found->second) {
                        if (j > i && (position[i] - position[j]).squaredNorm() < limit2) {
                            sets.join(i, j);
                        }
                    }
                }
            }
        }
    }
    std::vector<Index> size(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        ++size[sets.find(i)];
    }
    // max_element returns the first maximum: the cluster whose root (lowest index) is lowest.
    const auto biggest = static_cast<std::size_t>(
        std::distance(size.begin(), std::max_element(size.begin(), size.end())));
    for (std::size_t i = 0; i < n; ++i) {
        member[i] = sets.find(i) == biggest ? 1 : 0;
    }
    return member;
}

HeapMeasures measure_heap(const std::vector<Vec3>& position, const std::vector<double>& mass,
                          const HeapFrame& frame) {
    HeapMeasures result;
    const double dp = frame.spacing;
    const auto member = largest_cluster(position, 1.5 * dp);
    // The surface profile: per bin of width dp along the horizontal coordinate, the heap
    // particle with the highest top (its centre height + dp/2), taken at its own coordinate.
    std::vector<SurfaceSample> bins;
    double top = -std::numeric_limits<double>::infinity();
    double reach = -std::numeric_limits<double>::infinity();
    // The axis column: particles whose centre lies within dp of the axis (3D), or in the
    // first spacing in front of the back face (2D), where a deposit often dips below its
    // highest point.
    double axis_top = 0.0;
    for (std::size_t i = 0; i < position.size(); ++i) {
        if (!member[i]) {
            ++result.outside_count;
            continue;
        }
        ++result.heap_count;
        const Vec3 d = position[i] - frame.origin;
        const double height = d.dot(frame.up) + 0.5 * dp - frame.floor_level;
        const double c = horizontal(d, frame);
        top = std::max(top, height);
        reach = std::max(reach, c + 0.5 * dp);
        if (std::abs(c) < dp) {
            axis_top = std::max(axis_top, height);
        }
        const auto bin = static_cast<std::size_t>(std::max(0.0, std::floor(c / dp)));
        if (bin >= bins.size()) {
            bins.resize(bin + 1);
        }
        if (height > bins[bin].top) {
            bins[bin] = {c, height};
        }
    }
    if (result.heap_count == 0) {
        return result;
    }
    result.final_height = top;
    result.axis_height = axis_top;
    result.run_out = reach;
    result.run_out_99 = mass_run_out(position, mass, frame);
    result.angle = flank_angle(bins, top);
    return result;
}

void RestDetector::add(double time, double kinetic_energy) {
    last_ = kinetic_energy;
    if (kinetic_energy > peak_) {
        peak_ = kinetic_energy;
        peak_time_ = time;
        rest_time_ = -1.0;
    } else if (rest_time_ < 0.0 && kinetic_energy < fraction_ * peak_) {
        rest_time_ = time;
    }
}

std::optional<double> RestDetector::rest_time() const {
    return rest_time_ >= 0.0 ? std::optional<double>(rest_time_) : std::nullopt;
}

std::vector<double> RestDetector::state() const {
    return {peak_, peak_time_, rest_time_, last_};
}

void RestDetector::set_state(const std::vector<double>& state) {
    if (state.size() == 4) {
        peak_ = state[0];
        peak_time_ = state[1];
        rest_time_ = state[2];
        last_ = state[3];
    }
}

} // namespace grainload::sph
