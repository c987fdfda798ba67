#include "dem/sphere_set.hpp"

#include "particles/compact.hpp"

namespace grainload::dem {

void SphereSet::add(Index owner, double sphere_radius, const Vec3& own_offset) {
    id.push_back(next_id++);
    grain.push_back(owner);
    radius.push_back(sphere_radius);
    offset.push_back(own_offset);
    position.push_back(Vec3::Zero());
    arm.push_back(Vec3::Zero());
    contacts.push_back(0);
    springs.emplace_back();
}

void SphereSet::place(const GrainSet& grains) {
    const Index n = size();
#pragma omp parallel for schedule(static)
    for (Index s = 0; s < n; ++s) {
        const auto g = static_cast<std::size_t>(grain[s]);
        // A spherical grain's one sphere sits at its centre: nothing to turn.
        if (offset[s].isZero(0.0)) {
            arm[s] = Vec3::Zero();
            position[s] = grains.position[g];
            continue;
        }
        arm[s] = grains.orientation[g] * offset[s];
        position[s] = grains.position[g] + arm[s];
    }
}

void SphereSet::keep(std::span<const char> grain_gone, std::span<const Index> new_index) {
    std::vector<char> gone(id.size());
    for (std::size_t s = 0; s < id.size(); ++s) {
        gone[s] = grain_gone[static_cast<std::size_t>(grain[s])];
    }
    particles::compact(id, gone);
    particles::compact(grain, gone);
    particles::compact(radius, gone);
    particles::compact(offset, gone);
    particles::compact(position, gone);
    particles::compact(arm, gone);
    particles::compact(contacts, gone);
    particles::compact(springs, gone);
    for (Index& owner : grain) {
        owner = new_index[static_cast<std::size_t>(owner)];
    }
}

void SphereSet::first_of_grains(Index grains, std::vector<Index>& first) const {
    first.assign(static_cast<std::size_t>(grains) + 1, size());
    for (Index s = size() - 1; s >= 0; --s) {
        first[static_cast<std::size_t>(grain[s])] = s;
    }
    // A grain always has a sphere; the sentinel closes the last one's range.
    first[static_cast<std::size_t>(grains)] = size();
}

} // namespace grainload::dem
