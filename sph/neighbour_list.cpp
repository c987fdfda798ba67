#include "sph/neighbour_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace grainload::sph {

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

bool NeighbourList::update(std::span<const Vec3> positions, std::span<const char> frozen,
                           bool force) {
    const bool stale = force || skin_ == 0.0 || reference_.size() != positions.size() ||
                       2.0 * max_displacement(positions) > skin_;
    if (stale) {
        rebuild(positions, frozen);
    }
    return stale;
}

void NeighbourList::rebuild(std::span<const Vec3> positions, std::span<const char> frozen) {
    const auto n = static_cast<Index>(positions.size());
    if (n > std::numeric_limits<std::int32_t>::max()) {
        throw std::length_error("NeighbourList: more than 2^31 particles");
    }
    const double radius = search_radius();
    const double radius_squared = radius * radius;
    cells_.build(positions, radius, dimension_);
    const bool use_frozen = !frozen.empty();
    // A frozen particle (a wall's) pairs only with free ones, so it searches a grid of the free
    // particles alone: the same grid, so the same candidate order less the frozen ones, without
    // walking past its own wall's particles (most of the candidates of a wall particle).
    if (use_frozen) {
        free_cells_.build_subset(positions, cells_, frozen);
    }
    auto grid_of = [&](Index i) -> const CellList& {
        return use_frozen && frozen[i] ? free_cells_ : cells_;
    };
    auto keeps = [&](Index i, Index j) {
        return j != i && !(use_frozen && frozen[i] && frozen[j]) &&
               (positions[i] - positions[j]).squaredNorm() < radius_squared;
    };
    offset_.assign(static_cast<std::size_t>(n + 1), 0);
    // Two passes (count, then fill) keep the list in one allocation with no per-thread buffers.
#pragma omp parallel for schedule(dynamic, 256)
    for (Index i = 0; i < n; ++i) {
        Index count = 0;
        grid_of(i).for_each_candidate(positions[i], [&](Index j) { count += keeps(i, j) ? 1 : 0; });
        offset_[i + 1] = count;
    }
    for (Index i = 0; i < n; ++i) {
        offset_[i + 1] += offset_[i];
    }
    index_.resize(static_cast<std::size_t>(offset_[n]));
#pragma omp parallel for schedule(dynamic, 256)
    for (Index i = 0; i < n; ++i) {
        Index k = offset_[i];
        grid_of(i).for_each_candidate(positions[i], [&](Index j) {
            if (keeps(i, j)) {
                index_[k++] = static_cast<std::int32_t>(j);
            }
        });
    }
    reference_.assign(positions.begin(), positions.end());
    ++rebuilds_;
}

std::size_t NeighbourList::bytes() const {
    return offset_.capacity() * sizeof(Index) + index_.capacity() * sizeof(std::int32_t) +
           reference_.capacity() * sizeof(Vec3) + cells_.bytes() + free_cells_.bytes();
}

} // namespace grainload::sph
