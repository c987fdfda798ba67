#pragma once
// The same-body pair passes split into one part per thread, summed in order to repeat bit for bit.

#include "particles/neighbour_list.hpp"
#include "sph/particle_set.hpp"

#include <cstddef>
#include <cstdint>
#include <omp.h>
#include <span>
#include <vector>

namespace grainload::sph {

/// Which particles exchange stress: the key of particle (or mirror image) i is its body for a
/// material particle and a value no other particle has (-2 - i) for a wall particle, so two
/// keys are equal exactly for the pairs that exchange stress (same body, neither a wall
/// particle).
inline int continuum_key(bool wall, int body, Index i) {
    return wall ? static_cast<int>(-2 - i) : body;
}
/// continuum_key of every particle: one load per neighbour in the pair loops.
std::vector<int> continuum_keys(const ParticleSet& particles);

/// The passes over same-body pairs visit each pair once, from the row of its lower index, and
/// add its terms to both particles (Newton's third law in the force pass, the symmetric
/// velocity difference in the kinematic pass): half the pairs' arithmetic and neighbour loads
/// of a both-direction list. The rows are split into parts, one per thread; a part adds into
/// its own accumulators, the first part into the particles' arrays themselves, and the parts
/// are summed in their order afterwards. The split depends only on the list and the number of
/// parts, so a run repeats itself bit for bit at a given thread count; between thread counts
/// the sums are ordered differently (round-off).
///
/// Rows [bounds[r], bounds[r + 1]) of part r, for `parts` parts of about equal numbers of list
/// entries over the first `rows` rows.
std::vector<Index> balanced_rows(const particles::NeighbourList& list, Index rows, int parts);

/// Accumulators of the parts after the first: `width` doubles per particle each.
class PairScratch {
  public:
    /// Make room for `parts` parts (the first needs none) of n particles of `width` doubles.
    void reserve(int parts, Index n, int width);
    /// Part r's accumulators (r >= 1), as reserved; zero() them first.
    double* part(int r) { return parts_[static_cast<std::size_t>(r - 1)].data(); }
    /// Set part r's first `count` doubles to zero (by the thread that then fills them).
    void zero(int r, std::size_t count);
    std::size_t bytes() const;

  private:
    std::vector<std::vector<double>> parts_;
};

/// d = x_i - x_j in the first D components (plane strain: z is 0 and left out); returns |d|^2.
template <int D> double separation(const Vec3& xi, const Vec3& xj, double (&d)[D]) {
    double r2 = 0.0;
    for (int c = 0; c < D; ++c) {
        d[c] = xi[c] - xj[c];
        r2 += d[c] * d[c];
    }
    return r2;
}

/// The same-body pairs (i, j > i) among entries [first, end) of row i's list, in the list's
/// order, for the vector lanes (pair_lanes.hpp): each entry is written to `picked` and the end
/// moved on past the picked ones only (no branch: whether an entry of a halved row is picked
/// follows no pattern a predictor learns). `others`: entries of another key (contact partners).
struct PickedPairs {
    int count = 0;
    int others = 0;
};
inline PickedPairs pick_same_body_pairs(std::span<const std::int32_t> list, std::size_t first,
                                        std::size_t end, const std::vector<int>& key, Index i,
                                        std::int32_t* picked) {
    PickedPairs out;
    const int key_i = key[static_cast<std::size_t>(i)];
    for (std::size_t k = first; k < end; ++k) {
        const std::int32_t j = list[k];
        picked[out.count] = j;
        const bool same = key[static_cast<std::size_t>(j)] == key_i;
        out.count += same && j > i ? 1 : 0;
        out.others += same ? 0 : 1;
    }
    return out;
}

/// Number of parts of a pass: the threads OpenMP would use.
int pass_parts();

/// Runs row(i, r) for the rows i of each part r of `bounds` (balanced_rows), each part on one
/// thread and its rows in order; part r > 0's first `doubles` accumulators in `scratch` are
/// zeroed first, by that thread.
template <class Row>
void for_each_part(const std::vector<Index>& bounds, PairScratch& scratch, std::size_t doubles,
                   const Row& row) {
    const int parts = static_cast<int>(bounds.size()) - 1;
#pragma omp parallel num_threads(parts)
    for (int r = omp_get_thread_num(); r < parts; r += omp_get_num_threads()) {
        if (r > 0) {
            scratch.zero(r, doubles);
        }
        for (Index i = bounds[r]; i < bounds[r + 1]; ++i) {
            row(i, r);
        }
    }
}

} // namespace grainload::sph
