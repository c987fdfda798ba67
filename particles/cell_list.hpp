#pragma once
// The uniform grid of cells in which the neighbours of particles are searched.

#include "io/types.hpp"

#include <algorithm>
#include <array>
#include <span>
#include <vector>

namespace grainload::particles {

/// Uniform grid of cells of edge >= the search radius: the neighbours of a particle lie in its
/// own cell and the adjacent ones (9 in plane strain, 27 in 3D). Particles are binned by a
/// counting sort, so a build is O(N) and allocates only when the grid grows.
///
/// The grid's cells are stored densely up to a few per particle; a scene whose box needs more
/// (a few particles far from the rest) first takes coarser cells. Where that would put many
/// particles in one cell (a wall millions of spacings from the sand: the search turned
/// quadratic), the grid keeps cells of the search radius and stores only the occupied ones:
/// the particles sorted by cell, a cell's start found by binary search over their sorted cell
/// numbers. The order of the particles, and of the candidates, is the dense grid's.
class CellList {
  public:
    /// dimension 2 keeps a single layer of cells in z.
    void build(std::span<const Vec3> positions, double search_radius, int dimension);
    /// The grid of `like` (origin, cell size and counts), holding only the particles i with
    /// !skip[i]: candidates come in the same order as from `like`, less the skipped ones.
    void build_subset(std::span<const Vec3> positions, const CellList& like,
                      std::span<const char> skip);

    /// Call visit(j) for every particle j in the cells around x (including x's own particle).
    template <class Visit> void for_each_candidate(const Vec3& x, Visit&& visit) const {
        for_each_range(x, [&](Index begin, Index end) {
            for (Index k = begin; k < end; ++k) {
                visit(sorted_[k]);
            }
        });
    }

    /// Call visit(begin, end) for each run [begin, end) of sorted positions around x, in the
    /// order for_each_candidate visits them: sorted()[k] and the coordinates at k.
    template <class Visit> void for_each_range(const Vec3& x, Visit&& visit) const {
        const auto c = cell_coordinates(x);
        const int z_reach = cells_[2] > 1 ? 1 : 0;
        for (int dz = -z_reach; dz <= z_reach; ++dz) {
            const Index z = c[2] + dz;
            if (z < 0 || z >= cells_[2]) {
                continue;
            }
            for (int dy = -1; dy <= 1; ++dy) {
                const Index y = c[1] + dy;
                if (y < 0 || y >= cells_[1]) {
                    continue;
                }
                const Index row = (z * cells_[1] + y) * cells_[0];
                const Index x_first = c[0] > 0 ? c[0] - 1 : 0;
                const Index x_last = c[0] + 1 < cells_[0] ? c[0] + 1 : cells_[0] - 1;
                // Cells adjacent in x are contiguous in the sorted order: one range per row.
                visit(cell_start(row + x_first), cell_start(row + x_last + 1));
            }
        }
    }

    Index cell_count() const { return cells_[0] * cells_[1] * cells_[2]; }
    /// Whether only the occupied cells are stored (see the class comment).
    bool sparse() const { return sparse_; }
    /// Particle indices in cell order, and their coordinates in the same order (contiguous, so
    /// that a search loop over a run of them vectorises).
    const Index* sorted() const { return sorted_.data(); }
    const double* sorted_coordinate(int axis) const { return coordinates_[axis].data(); }
    /// Heap bytes held (cell starts, sorted indices and coordinates).
    std::size_t bytes() const {
        return (cell_start_.capacity() + sorted_.capacity() + sorted_cell_.capacity()) *
                   sizeof(Index) +
               (coordinates_[0].capacity() + coordinates_[1].capacity() +
                coordinates_[2].capacity()) *
                   sizeof(double);
    }
    double cell_size() const { return cell_size_; }

  private:
    std::array<Index, 3> cell_coordinates(const Vec3& x) const;
    /// The first sorted position of cell c or of a later one.
    Index cell_start(Index c) const {
        if (!sparse_) {
            return cell_start_[c];
        }
        return std::lower_bound(sorted_cell_.begin(), sorted_cell_.end(), c) - sorted_cell_.begin();
    }
    /// Counting sort of the particles i with !skip[i] (all with an empty skip) into the grid.
    void bin(std::span<const Vec3> positions, std::span<const char> skip);
    /// sorted_ from each particle's cell (negative: skipped), by a counting sort over every
    /// cell or a sort of the occupied ones; returns the particles sorted.
    Index sort_dense(const std::vector<Index>& cell);
    Index sort_sparse(const std::vector<Index>& cell);

    Vec3 origin_ = Vec3::Zero();
    double cell_size_ = 1.0;
    std::array<Index, 3> cells_{1, 1, 1};
    bool sparse_ = false;
    std::vector<Index> cell_start_;                  ///< dense: size cell_count() + 1
    std::vector<Index> sorted_cell_;                 ///< sparse: the cell of sorted_[k] at k
    std::vector<Index> sorted_;                      ///< particle indices ordered by cell
    std::array<std::vector<double>, 3> coordinates_; ///< x, y, z of sorted_[k] at k
};

} // namespace grainload::particles
