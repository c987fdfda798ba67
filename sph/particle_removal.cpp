#include "sph/particle_removal.hpp"

#include <stdexcept>

namespace grainload::sph {

namespace {

/// The material state blocks of the kept particles, moved down in order, and the kept
/// particles' state_offset pointed at their new place (compacted with the other fields after).
void compact_state(ParticleSet& p, std::span<const char> gone) {
    const auto n = p.state_offset.size();
    std::size_t kept = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto begin = static_cast<std::size_t>(p.state_offset[i]);
        const auto end =
            i + 1 < n ? static_cast<std::size_t>(p.state_offset[i + 1]) : p.state.size();
        if (gone[i]) {
            continue;
        }
        p.state_offset[i] = static_cast<Index>(kept);
        for (std::size_t k = begin; k < end; ++k) {
            p.state[kept++] = p.state[k];
        }
    }
    p.state.resize(kept);
}

/// A wall's per-particle array (empty or one entry per particle of the wall).
template <class T>
void compact_wall_array(std::vector<T>& values, std::span<const char> gone, Index first) {
    if (!values.empty()) {
        particles::compact(values, gone.subspan(static_cast<std::size_t>(first), values.size()));
    }
}

} // namespace

std::vector<Index> remove_particles(ParticleSet& p, std::span<const char> gone,
                                    std::vector<Wall>& walls) {
    const auto n = static_cast<std::size_t>(p.size());
    if (gone.size() != n) {
        throw std::invalid_argument("remove_particles: one flag per particle expected");
    }
    // kept_before[i]: kept particles below index i, the new index of particle i if it stays.
    std::vector<Index> kept_before(n, 0);
    std::vector<Index> new_index(n, -1);
    Index kept = 0;
    for (std::size_t i = 0; i < n; ++i) {
        kept_before[i] = kept;
        if (!gone[i]) {
            new_index[i] = kept++;
        }
    }
    auto before = [&](std::size_t i) { return i < n ? kept_before[i] : kept; };
    for (Wall& wall : walls) {
        // The wall's kept particles stay contiguous, right after the kept ones before it.
        const auto first = static_cast<std::size_t>(wall.first);
        const auto end = static_cast<std::size_t>(wall.first + wall.count);
        compact_wall_array(wall.normals, gone, wall.first);
        compact_wall_array(wall.angular_velocities, gone, wall.first);
        compact_wall_array(wall.samples, gone, wall.first);
        wall.first = before(first);
        wall.count = before(end) - before(first);
    }
    compact_state(p, gone);
    p.for_each_field([gone](const auto&, auto& values) { particles::compact(values, gone); });
    return new_index;
}

} // namespace grainload::sph
