#pragma once
// Dropping the entries of departed particles from a per-particle array, in order.

#include <span>
#include <utility>
#include <vector>

namespace grainload::particles {

/// Keep the entries of `values` whose `gone` flag is 0, in order (one flag per entry).
template <class T> void compact(std::vector<T>& values, std::span<const char> gone) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!gone[i]) {
            if (kept != i) {
                values[kept] = std::move(values[i]);
            }
            ++kept;
        }
    }
    values.resize(kept);
}

} // namespace grainload::particles
