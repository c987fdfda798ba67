#include "particles/cell_list.hpp"

#include "particles/point_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace grainload::particles {

namespace {

/// Cap on cells per particle: a few particles flying far away must not allocate a huge grid.
constexpr double kMaxCellsPerParticle = 8.0;

/// Coarsening beyond this factor of the search radius stores the occupied cells instead. A
/// coarsened cell holds c^3 times the candidates (c^2 in plane strain): at c = 1.5 a particle
/// still tests about 3.4 times its 27 cells' worth, a vectorised distance test each, cheaper
/// than the sparse grid's 18 binary searches; from c = 3.4 (38 times) the searches win.
constexpr double kSparseBeyond = 2.5;

/// Cells per axis of the sparse grid: (2^20)^3 cell numbers fit an Index. Positions beyond
/// take the last cell, as the dense grid's do (cell_coordinates).
constexpr double kSparseAxisCells = 1048576.0;

} // namespace

std::array<Index, 3> CellList::cell_coordinates(const Vec3& x) const {
    std::array<Index, 3> c{};
    for (int a = 0; a < 3; ++a) {
        // Clamped while still a double: a particle far outside the grid, or at infinity or NaN
        // (gone astray; the diagnosis names it after the step), takes the nearest cell, and
        // the cast to an integer stays defined.
        const double k = std::floor((x[a] - origin_[a]) / cell_size_);
        const auto last = cells_[a] - 1;
        c[a] = k >= 0.0 ? (k < static_cast<double>(last) ? static_cast<Index>(k) : last) : 0;
    }
    return c;
}

void CellList::build(std::span<const Vec3> positions, double search_radius, int dimension) {
    if (!(search_radius > 0.0)) {
        throw std::invalid_argument("CellList: search radius must be positive");
    }
    const auto n = static_cast<Index>(positions.size());
    // The grid spans the finite positions; a non-finite one goes to the nearest cell.
    const PointBounds box =
        point_bounds(positions, [&positions](Index i) { return positions[i].allFinite(); });
    const Vec3 lower = box.empty() ? Vec3::Zero() : box.lower;
    const Vec3 upper = box.empty() ? Vec3::Zero() : box.upper;
    origin_ = lower;
    cell_size_ = search_radius;
    const double budget = kMaxCellsPerParticle * static_cast<double>(std::max<Index>(n, 1)) + 27.0;
    // Cells per axis at cell_size_, each capped at `cap`; returns their uncapped product. Counted
    // in doubles (half extents: no overflow even for +-1e308), so that particles flung far away
    // coarsen the grid instead of overflowing its integer size.
    auto size_grid = [&](double cap) {
        double count = 1.0;
        for (int a = 0; a < 3; ++a) {
            const bool flat = a == 2 && dimension == 2;
            const double span = 2.0 * ((0.5 * upper[a] - 0.5 * lower[a]) / cell_size_);
            cells_[a] = flat ? 1 : static_cast<Index>(std::min(span, cap)) + 1;
            count *= flat ? 1.0 : span + 1.0;
        }
        return count;
    };
    while (size_grid(budget) > budget) {
        cell_size_ *= 1.5;
    }
    sparse_ = cell_size_ > kSparseBeyond * search_radius;
    if (sparse_) {
        cell_size_ = search_radius;
        size_grid(kSparseAxisCells - 1.0);
    }
    bin(positions, {});
}

void CellList::build_subset(std::span<const Vec3> positions, const CellList& like,
                            std::span<const char> skip) {
    origin_ = like.origin_;
    cell_size_ = like.cell_size_;
    cells_ = like.cells_;
    sparse_ = like.sparse_;
    bin(positions, skip);
}

Index CellList::sort_dense(const std::vector<Index>& cell) {
    const auto n = static_cast<Index>(cell.size());
    sorted_cell_.clear();
    cell_start_.assign(static_cast<std::size_t>(cell_count() + 1), 0);
    Index count = 0;
    for (Index i = 0; i < n; ++i) {
        if (cell[i] >= 0) {
            ++cell_start_[cell[i] + 1];
            ++count;
        }
    }
    for (Index c = 0; c < cell_count(); ++c) {
        cell_start_[c + 1] += cell_start_[c];
    }
    sorted_.resize(static_cast<std::size_t>(count));
    std::vector<Index> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (Index i = 0; i < n; ++i) {
        if (cell[i] >= 0) {
            sorted_[fill[cell[i]]++] = i;
        }
    }
    return count;
}

Index CellList::sort_sparse(const std::vector<Index>& cell) {
    const auto n = static_cast<Index>(cell.size());
    cell_start_.clear();
    sorted_.clear();
    for (Index i = 0; i < n; ++i) {
        if (cell[i] >= 0) {
            sorted_.push_back(i);
        }
    }
    // By cell, and by index within a cell: the counting sort's order.
    std::stable_sort(sorted_.begin(), sorted_.end(),
                     [&cell](Index a, Index b) { return cell[a] < cell[b]; });
    sorted_cell_.resize(sorted_.size());
    for (std::size_t k = 0; k < sorted_.size(); ++k) {
        sorted_cell_[k] = cell[sorted_[k]];
    }
    return static_cast<Index>(sorted_.size());
}

void CellList::bin(std::span<const Vec3> positions, std::span<const char> skip) {
    const auto n = static_cast<Index>(positions.size());
    // The cells are computed in parallel (the floor and division are most of the binning) and
    // kept only while binning: 8 bytes per particle less between builds. The counting sort
    // itself stays serial, so the order within a cell, and the neighbour lists, are the serial
    // ones.
    constexpr Index kSkipped = -1;
    std::vector<Index> cell(static_cast<std::size_t>(n));
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        if (skip.empty() || !skip[i]) {
            const auto c = cell_coordinates(positions[i]);
            cell[i] = (c[2] * cells_[1] + c[1]) * cells_[0] + c[0];
        } else {
            cell[i] = kSkipped;
        }
    }
    const Index count = sparse_ ? sort_sparse(cell) : sort_dense(cell);
    for (int axis = 0; axis < 3; ++axis) {
        coordinates_[axis].resize(static_cast<std::size_t>(count));
    }
#pragma omp parallel for schedule(static)
    for (Index k = 0; k < count; ++k) {
        const Vec3& x = positions[sorted_[k]];
        coordinates_[0][k] = x[0];
        coordinates_[1][k] = x[1];
        coordinates_[2][k] = x[2];
    }
}

} // namespace grainload::particles
