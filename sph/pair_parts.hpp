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
/// Part r's rows are [bounds[r], bounds[r + 1]), of about equal numbers of list entries; its
/// pair terms go to particles [bounds[r], reach[r]) (a row adds to itself and to the j > i of
/// its same-key pairs, never to a wall particle), so a later part's accumulators span that
/// window only, not the wall particles and the rows before it. (More parts than threads, taken
/// as threads come free, balanced no better on the 2D collapse and the 3D block and cost more:
/// once grains have flowed, a part's pairs reach far along the particles' order, and each
/// window is zeroed and summed; docs/performance.md.)
struct PairParts {
    std::vector<Index> bounds;
    std::vector<Index> reach;
    int count() const { return static_cast<int>(bounds.size()) - 1; }
    /// Part r's first particle in its accumulators (0 for the first part, which adds into the
    /// particles' arrays).
    Index origin(int r) const { return r == 0 ? 0 : bounds[static_cast<std::size_t>(r)]; }
    /// Particles in part r's window.
    Index window(int r) const {
        return reach[static_cast<std::size_t>(r)] - bounds[static_cast<std::size_t>(r)];
    }
};

/// `parts` parts over the first `rows` rows, and their reach among the `particles` particles
/// (all of them where the list is not halved()).
PairParts split_rows(const particles::NeighbourList& list, Index rows, Index particles, int parts);

/// Accumulators of the parts after the first: `width` doubles per particle of each part's
/// window.
class PairScratch {
  public:
    /// Make room for the windows of `parts` (the first needs none), `width` doubles a particle.
    void reserve(const PairParts& parts, int width);
    /// Part r's accumulators (r >= 1), as reserved: particle k's at part(r) + width (k -
    /// origin(r)); zero() them first.
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

/// Runs row(i, r) for the rows i of each part r of `parts` (split_rows), each part on one thread
/// and its rows in order; part r > 0's `width` doubles a particle of its window in `scratch`
/// are zeroed first, by the thread that runs it.
template <class Row>
void for_each_part(const PairParts& parts, PairScratch& scratch, int width, const Row& row) {
    const int count = parts.count();
#pragma omp parallel for schedule(static, 1)
    for (int r = 0; r < count; ++r) {
        const auto part = static_cast<std::size_t>(r);
        if (r > 0) {
            scratch.zero(r, static_cast<std::size_t>(width) *
                                static_cast<std::size_t>(parts.window(r)));
        }
        for (Index i = parts.bounds[part]; i < parts.bounds[part + 1]; ++i) {
            row(i, r);
        }
    }
}

/// Calls add(r, k) for each part r after the first whose window holds particle i, in the
/// parts' order, with k = i - origin(r) its place there: the order in which the parts' sums of i
/// are added to the first part's.
template <class Add> void for_later_parts(const PairParts& parts, Index i, const Add& add) {
    for (int r = 1; r < parts.count() && parts.bounds[static_cast<std::size_t>(r)] <= i; ++r) {
        if (i < parts.reach[static_cast<std::size_t>(r)]) {
            add(r, i - parts.origin(r));
        }
    }
}

} // namespace grainload::sph
