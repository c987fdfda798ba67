#pragma once
// Sums over particles, reduced over the threads in an order that does not depend on their number.

#include "io/types.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace grainload::particles {

/// Terms per block of ordered_sums.
inline constexpr Index kOrderedSumBlock = 1024;
/// Blocks from which ordered_sums spreads them over the threads: below, one thread sums them
/// (a sum over 1e4 particles takes about 10 us, which a parallel loop's start and end, with a
/// waiting thread to wake, would cost again). The result's bits are the same either way.
inline constexpr Index kOrderedSumParallelBlocks = 32;

/// N sums over i in [0, n): add(i, sums) adds particle i's terms to the N sums of its block
/// (and may update particle i: it is called once for each i). Blocks of kOrderedSumBlock
/// particles are summed in order, on any thread, and the blocks' sums then added in order: the
/// blocks are fixed by n alone, so the result is the same bits on any number of threads (a
/// reduction clause's is not), and for n up to one block it is the plain serial sum's. For the
/// energy books that a run keeps every step. The blocks are spread over the threads from
/// `parallel_blocks` blocks on: 0 for a loop that also updates the particles.
template <std::size_t N, class Add>
std::array<double, N> ordered_sums(Index n, const Add& add,
                                   Index parallel_blocks = kOrderedSumParallelBlocks) {
    const Index blocks = (n + kOrderedSumBlock - 1) / kOrderedSumBlock;
    std::vector<std::array<double, N>> partial(static_cast<std::size_t>(blocks));
    // Dynamic: blocks of wall particles, which most sums skip, lie beside blocks of grains.
#pragma omp parallel for schedule(dynamic, 1) if (blocks >= parallel_blocks)
    for (Index b = 0; b < blocks; ++b) {
        std::array<double, N> sums{};
        const Index end = std::min(n, (b + 1) * kOrderedSumBlock);
        for (Index i = b * kOrderedSumBlock; i < end; ++i) {
            add(i, sums);
        }
        partial[static_cast<std::size_t>(b)] = sums;
    }
    std::array<double, N> total{};
    for (const auto& sums : partial) {
        for (std::size_t k = 0; k < N; ++k) {
            total[k] += sums[k];
        }
    }
    return total;
}

/// One sum of term(i) over i in [0, n), as ordered_sums.
template <class Term>
double ordered_sum(Index n, const Term& term, Index parallel_blocks = kOrderedSumParallelBlocks) {
    return ordered_sums<1>(
        n, [&](Index i, std::array<double, 1>& sums) { sums[0] += term(i); }, parallel_blocks)[0];
}

} // namespace grainload::particles
