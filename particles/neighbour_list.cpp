#include "particles/neighbour_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace grainload::particles {

NeighbourList::NeighbourList(double support_radius, double skin, int dimension)
    : support_(support_radius), skin_(skin), dimension_(dimension) {
    if (!(support_radius > 0.0) || skin < 0.0) {
        throw std::invalid_argument("NeighbourList: support must be > 0 and skin >= 0");
    }
}

double NeighbourList::max_displacement(std::span<const Vec3> positions) const {
    const auto n = static_cast<Index>(positions.size());
    double largest_squared = 0.0;
#pragma omp parallel for reduction(max : largest_squared) schedule(static)
    for (Index i = 0; i < n; ++i) {
        largest_squared = std::max(largest_squared, (positions[i] - reference_[i]).squaredNorm());
    }
    return std::sqrt(largest_squared);
}

bool NeighbourList::stale(std::span<const Vec3> positions) const {
    return skin_ == 0.0 || reference_.size() != positions.size() ||
           2.0 * max_displacement(positions) > skin_;
}

bool NeighbourList::update(std::span<const Vec3> positions, std::span<const char> frozen,
                           bool force, Index rows) {
    const bool rebuild_now = force || stale(positions);
    if (rebuild_now) {
        rebuild(positions, frozen, rows < 0 ? static_cast<Index>(positions.size()) : rows);
    }
    return rebuild_now;
}

const CellList& NeighbourList::search_grid(std::span<const char> frozen, Index i) const {
    return !frozen.empty() && frozen[i] ? free_cells_ : cells_;
}

void NeighbourList::rebuild(std::span<const Vec3> positions, std::span<const char> frozen,
                            Index rows) {
    const auto n = static_cast<Index>(positions.size());
    if (n > std::numeric_limits<std::int32_t>::max()) {
        throw std::length_error("NeighbourList: more than 2^31 particles");
    }
    const double radius = search_radius();
    cells_.build(positions, radius, dimension_);
    // A frozen particle (a wall's) pairs only with free ones, so it searches a grid of the free
    // particles alone: the same grid, so the same candidate order less the frozen ones, without
    // walking past its own wall's particles (most of the candidates of a wall particle).
    if (!frozen.empty()) {
        free_cells_.build_subset(positions, cells_, frozen);
    }
    // Two passes (count, then fill) keep the list in one allocation with no per-thread buffers.
    count_rows(positions, frozen, rows, radius * radius);
    for (Index i = 0; i < n; ++i) {
        offset_[i + 1] += offset_[i];
    }
    index_.resize(static_cast<std::size_t>(offset_[n]));
    fill_rows(positions, frozen, rows, radius * radius);
    reference_.assign(positions.begin(), positions.end());
    same_key_row_.clear();
    reach_before_.clear();
    ++rebuilds_;
    ++generation_;
}

void NeighbourList::count_rows(std::span<const Vec3> positions, std::span<const char> frozen,
                               Index rows, double radius_squared) {
    offset_.assign(positions.size() + 1, 0);
#pragma omp parallel for schedule(dynamic, 256)
    for (Index i = 0; i < rows; ++i) {
        const CellList& grid = search_grid(frozen, i);
        const Vec3 x = positions[i];
        const double* gx = grid.sorted_coordinate(0);
        const double* gy = grid.sorted_coordinate(1);
        const double* gz = grid.sorted_coordinate(2);
        Index count = 0;
        // Counted without the test j != i, so that the loop vectorises; i itself passed the
        // distance test if it is in this grid (not a frozen particle's free grid) and its
        // distance to itself, 0 or NaN for a position that is not finite, is below the radius.
        const double x0 = x[0];
        const double x1 = x[1];
        const double x2 = x[2];
        grid.for_each_range(x, [&](Index begin, Index end) {
            // Whole numbers below 2^53 add exactly in any order, so the SIMD reduction that
            // lets SSE2 vectorise the count (it cannot turn a double comparison into a 64-bit
            // integer) changes nothing.
            double run = 0.0;
#pragma omp simd reduction(+ : run)
            for (Index k = begin; k < end; ++k) {
                const double dx = x0 - gx[k];
                const double dy = x1 - gy[k];
                const double dz = x2 - gz[k];
                run += dx * dx + dy * dy + dz * dz < radius_squared ? 1.0 : 0.0;
            }
            count += static_cast<Index>(run);
        });
        const bool counted_itself = &grid == &cells_ && (x - x).squaredNorm() < radius_squared;
        offset_[i + 1] = count - (counted_itself ? 1 : 0);
    }
}

void NeighbourList::fill_rows(std::span<const Vec3> positions, std::span<const char> frozen,
                              Index rows, double radius_squared) {
    // Whether candidate k of `grid` is a neighbour of i: the distance as
    // (x_i - x_j).squaredNorm() computes it, from the grid's contiguous coordinates. Frozen
    // pairs never meet (a frozen particle searches the free grid), so no test for them.
    auto within = [radius_squared](const CellList& grid, const Vec3& x, Index i, Index k) {
        const double dx = x[0] - grid.sorted_coordinate(0)[k];
        const double dy = x[1] - grid.sorted_coordinate(1)[k];
        const double dz = x[2] - grid.sorted_coordinate(2)[k];
        return (dx * dx + dy * dy + dz * dz < radius_squared) & (grid.sorted()[k] != i);
    };
    // The fill without a branch per candidate (one in six or seven is a neighbour, in no
    // pattern a predictor could learn): every candidate is written to the row's buffer and the
    // end moves on only past the neighbours; the row's neighbours are then copied in order.
#pragma omp parallel
    {
        std::vector<std::int32_t> buffer;
#pragma omp for schedule(dynamic, 256)
        for (Index i = 0; i < rows; ++i) {
            const CellList& grid = search_grid(frozen, i);
            const Vec3 x = positions[i];
            std::size_t count = 0;
            grid.for_each_range(x, [&](Index begin, Index end) {
                const auto needed = count + static_cast<std::size_t>(end - begin);
                if (buffer.size() < needed) {
                    buffer.resize(2 * needed);
                }
                std::int32_t* out = buffer.data();
                for (Index k = begin; k < end; ++k) {
                    out[count] = static_cast<std::int32_t>(grid.sorted()[k]);
                    count += within(grid, x, i, k) ? 1 : 0;
                }
            });
            std::copy_n(buffer.data(), count, index_.data() + offset_[i]);
        }
    }
}

template <class Keep> void NeighbourList::keep_pairs(Keep keep) {
    const auto n = static_cast<Index>(offset_.size()) - 1;
    // Count, then copy, as rebuild() fills the list: one allocation, rows in parallel.
    std::vector<Index> offset(static_cast<std::size_t>(n + 1), 0);
#pragma omp parallel for schedule(dynamic, 256)
    for (Index i = 0; i < n; ++i) {
        Index count = 0;
        for (Index e = offset_[i]; e < offset_[i + 1]; ++e) {
            count += keep(i, index_[e]) ? 1 : 0;
        }
        offset[i + 1] = count;
    }
    for (Index i = 0; i < n; ++i) {
        offset[i + 1] += offset[i];
    }
    std::vector<std::int32_t> index(static_cast<std::size_t>(offset[n]));
#pragma omp parallel for schedule(dynamic, 256)
    for (Index i = 0; i < n; ++i) {
        Index entry = offset[i];
        for (Index e = offset_[i]; e < offset_[i + 1]; ++e) {
            if (keep(i, index_[e])) {
                index[entry++] = index_[e];
            }
        }
    }
    offset_ = std::move(offset);
    index_ = std::move(index);
    same_key_row_.clear();
    reach_before_.clear();
    ++generation_;
}

void NeighbourList::drop_pairs(std::span<const int> group, std::span<const char> apart,
                               int groups) {
    keep_pairs([&](Index i, std::int32_t j) {
        return apart[static_cast<std::size_t>(group[i]) * static_cast<std::size_t>(groups) +
                     static_cast<std::size_t>(group[j])] == 0;
    });
}

void NeighbourList::halve_pairs(std::span<const int> key) {
    keep_pairs([&](Index i, std::int32_t j) { return j > i || key[i] != key[j]; });
    const auto n = static_cast<Index>(offset_.size()) - 1;
    same_key_row_.assign(static_cast<std::size_t>(n), 0);
    reach_before_.assign(static_cast<std::size_t>(n + 1), 0);
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        bool all_same = true;
        std::int32_t reach = 0;
        for (const std::int32_t j : neighbours(i)) {
            const bool same = key[i] == key[j]; // then j > i: the pair's other row lost it
            all_same = all_same && same;
            reach = same ? std::max(reach, j + 1) : reach;
        }
        same_key_row_[static_cast<std::size_t>(i)] = all_same;
        reach_before_[static_cast<std::size_t>(i) + 1] = reach;
    }
    // Prefix maxima, serial: one pass over the rows per rebuild.
    for (std::size_t row = 1; row <= static_cast<std::size_t>(n); ++row) {
        reach_before_[row] = std::max(reach_before_[row], reach_before_[row - 1]);
    }
}

std::size_t NeighbourList::bytes() const {
    return offset_.capacity() * sizeof(Index) + index_.capacity() * sizeof(std::int32_t) +
           reference_.capacity() * sizeof(Vec3) + same_key_row_.capacity() +
           reach_before_.capacity() * sizeof(std::int32_t) + cells_.bytes() + free_cells_.bytes();
}

} // namespace grainload::particles
