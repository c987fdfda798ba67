#include "sph/pair_parts.hpp"

#include <algorithm>
#include <omp.h>

namespace grainload::sph {

std::vector<int> continuum_keys(const ParticleSet& p) {
    std::vector<int> key(static_cast<std::size_t>(p.size()));
    const Index n = p.size();
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) {
        key[i] = continuum_key(p.wall_id[i] >= 0, p.body_id[i], i);
    }
    return key;
}

PairParts split_rows(const particles::NeighbourList& list, Index rows, Index particles, int parts) {
    PairParts split;
    split.bounds.assign(static_cast<std::size_t>(parts) + 1, rows);
    split.bounds[0] = 0;
    const bool halved = list.halved();
    const Index entries = rows > 0 ? list.first_entry(rows) : 0;
    for (int r = 1; r < parts; ++r) {
        const Index target = entries * r / parts;
        // The first row whose entries begin at or after the target: rows are whole.
        Index low = split.bounds[static_cast<std::size_t>(r) - 1];
        Index high = rows;
        while (low < high) {
            const Index middle = low + (high - low) / 2;
            if (list.first_entry(middle) < target) {
                low = middle + 1;
            } else {
                high = middle;
            }
        }
        split.bounds[static_cast<std::size_t>(r)] = low;
    }
    split.reach.resize(static_cast<std::size_t>(parts));
    for (std::size_t r = 0; r < split.reach.size(); ++r) {
        // The prefix maximum over all rows before the part's end bounds its own rows' reach.
        const Index end = split.bounds[r + 1];
        split.reach[r] = halved ? std::max(end, list.same_key_reach_before(end)) : particles;
    }
    return split;
}

void PairScratch::reserve(const PairParts& parts, int width) {
    parts_.resize(static_cast<std::size_t>(std::max(parts.count() - 1, 0)));
    for (int r = 1; r < parts.count(); ++r) {
        const auto size =
            static_cast<std::size_t>(parts.window(r)) * static_cast<std::size_t>(width);
        auto& window = parts_[static_cast<std::size_t>(r) - 1];
        if (window.size() < size) {
            window.resize(size);
        }
    }
}

void PairScratch::zero(int r, std::size_t count) {
    std::fill_n(part(r), count, 0.0);
}

std::size_t PairScratch::bytes() const {
    std::size_t sum = 0;
    for (const auto& part : parts_) {
        sum += part.capacity() * sizeof(double);
    }
    return sum;
}

int pass_parts() {
    return std::max(1, omp_get_max_threads());
}

} // namespace grainload::sph
