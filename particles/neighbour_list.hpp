#pragma once
// The neighbour list of a particle set: pairs within reach + a Verlet skin, rebuilt when stale.

#include "particles/cell_list.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace grainload::particles {

/// Neighbour list in compressed rows: the neighbours of i are index[offset[i] .. offset[i+1]).
/// As built, each pair appears in both rows, so a loop over i can gather from its neighbours in
/// parallel with no atomics; halve_pairs then leaves the pairs that the passes take once in one
/// row.
///
/// Verlet list (Verlet 1967): pairs are collected within support + skin and the list is reused
/// until some particle has moved more than half the skin since the last build; then no pair
/// within the support can be missing. skin = 0 gives a plain cell-list search every step.
class NeighbourList {
  public:
    NeighbourList(double support_radius, double skin, int dimension);

    /// Rebuild if needed (or always when `force`). `frozen[i] && frozen[j]` pairs are left out
    /// (wall particles do not interact with each other); pass an empty span to keep all.
    /// Rows i >= `rows` (when >= 0) are left empty: mirror images (a symmetry plane's copies) are
    /// seen by the particles before them but have no neighbours of their own.
    /// Returns whether the list was rebuilt.
    bool update(std::span<const Vec3> positions, std::span<const char> frozen, bool force = false,
                Index rows = -1);
    /// Leave out the pairs whose particles' groups are kept apart: entry (i, j) goes when
    /// apart[group[i] * groups + group[j]] is nonzero (a wall and the bodies it does not act on).
    /// The list must have just been rebuilt: it holds no such pair until the next rebuild, which
    /// needs another call. `group` covers every position the list was built on.
    void drop_pairs(std::span<const int> group, std::span<const char> apart, int groups);
    /// Keep each pair of equal keys (a method's pairs within one body, neither a
    /// wall particle) in the row of its lower index only, for the passes that take such a pair
    /// once; the other pairs stay in both rows. Like drop_pairs, until the next rebuild.
    void halve_pairs(std::span<const int> key);
    /// Whether row i holds only pairs of equal keys, each taken in this row (j > i), as
    /// halve_pairs leaves the rows of particles that touch no other body or wall: the passes
    /// then hand the row to the vector lanes as it is, without picking its entries. False for
    /// every row until halve_pairs, and again after a rebuild or drop_pairs.
    bool same_key_row(Index i) const {
        return !same_key_row_.empty() && same_key_row_[static_cast<std::size_t>(i)] != 0;
    }
    /// Whether halve_pairs left the list as it is (until a rebuild or drop_pairs): only then
    /// does same_key_reach_before hold.
    bool halved() const { return !reach_before_.empty(); }
    /// One past the largest index j of a same-key pair in the rows before row i (i up to the row
    /// count) of a halved() list, 0 if none: the particles that the passes taking those rows'
    /// pairs add to lie below it.
    Index same_key_reach_before(Index i) const {
        return reach_before_[static_cast<std::size_t>(i)];
    }
    /// Whether update() would rebuild without `force`.
    bool stale(std::span<const Vec3> positions) const;

    /// 32-bit entries: the list is most of the memory per particle (4 bytes per pair entry).
    std::span<const std::int32_t> neighbours(Index i) const {
        return {index_.data() + offset_[i], static_cast<std::size_t>(offset_[i + 1] - offset_[i])};
    }
    Index pair_entries() const { return offset_.empty() ? 0 : offset_.back(); }
    /// Position of row i's first entry among all pair_entries(): per-entry arrays index by it.
    Index first_entry(Index i) const { return offset_[i]; }
    Index rebuild_count() const { return rebuilds_; }
    /// Changes whenever the list's pairs change (a rebuild, drop_pairs, halve_pairs): what is
    /// derived from the list can be kept until it does.
    Index generation() const { return generation_; }
    double search_radius() const { return support_ + skin_; }
    double skin() const { return skin_; }
    /// Positions at the last build: a checkpoint stores them so that a restart rebuilds the same
    /// list (same pairs, same order) that the uninterrupted run is still using.
    std::span<const Vec3> reference() const { return reference_; }
    /// Heap bytes held by the list and its cell grid, for the memory figures of the benchmark.
    std::size_t bytes() const;

  private:
    template <class Keep> void keep_pairs(Keep keep);
    void rebuild(std::span<const Vec3> positions, std::span<const char> frozen, Index rows);
    /// The grid particle i searches: the free particles' for a frozen one, else all of them.
    const CellList& search_grid(std::span<const char> frozen, Index i) const;
    /// offset_[i + 1] = row i's neighbour count, for the first `rows` rows (the rest 0).
    void count_rows(std::span<const Vec3> positions, std::span<const char> frozen, Index rows,
                    double radius_squared);
    /// The neighbours of the first `rows` rows into index_, at the offsets counted.
    void fill_rows(std::span<const Vec3> positions, std::span<const char> frozen, Index rows,
                   double radius_squared);
    double max_displacement(std::span<const Vec3> positions) const;

    double support_;
    double skin_;
    int dimension_;
    CellList cells_;
    CellList free_cells_; ///< the same grid holding only the particles that are not frozen
    std::vector<Index> offset_;
    std::vector<std::int32_t> index_;
    std::vector<Vec3> reference_;            ///< positions at the last build
    std::vector<char> same_key_row_;         ///< per row, set by halve_pairs (same_key_row)
    std::vector<std::int32_t> reach_before_; ///< prefix maxima of a row's largest same-key j + 1
    Index rebuilds_ = 0;
    Index generation_ = 0;
};

} // namespace grainload::particles
