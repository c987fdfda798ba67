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

std::vector<Index> balanced_rows(const particles::NeighbourList& list, Index rows, int parts) {
    std::vector<Index> bounds(static_cast<std::size_t>(parts) + 1, rows);
    bounds[0] = 0;
    const Index entries = rows > 0 ? list.first_entry(rows) : 0;
    for (int r = 1; r < parts; ++r) {
        const Index target = entries * r / parts;
        // The first row whose entries begin at or after the target: rows are whole.
        Index low = bounds[static_cast<std::size_t>(r) - 1];
        Index high = rows;
        while (low < high) {
            const Index middle = low + (high - low) / 2;
            if (list.first_entry(middle) < target) {
                low = middle + 1;
            } else {
                high = middle;
            }
        }
        bounds[static_cast<std::size_t>(r)] = low;
    }
    return bounds;
}

void PairScratch::reserve(int parts, Index n, int width) {
    parts_.resize(static_cast<std::size_t>(std::max(parts - 1, 0)));
    const auto size = static_cast<std::size_t>(n) * static_cast<std::size_t>(width);
    for (auto& part : parts_) {
        if (part.size() < size) {
            part.resize(size);
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
