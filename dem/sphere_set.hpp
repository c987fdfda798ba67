#pragma once
// The spheres that make the grains' surfaces: what touches, and the springs each keeps.

#include "dem/grain_set.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace grainload::dem {

/// The springs a sphere keeps with a partner: another sphere (its id) or a wall face
/// (kWallPartner + 2^32 wall + face): the tangential spring's stretch and the rolling spring's
/// torque. Kept by the sphere of the lower id of a pair, so that a grain's contacts travel with
/// it wherever it goes (another rank, a compacted set).
struct Spring {
    std::uint64_t partner = 0;
    Vec3 shear = Vec3::Zero();
    Vec3 rolling = Vec3::Zero();
};
inline constexpr std::uint64_t kWallPartner = std::uint64_t{1} << 63;

/// The spheres of the grains, in grain order (a grain's spheres are contiguous), one entry per
/// sphere in every field. A sphere sits at `offset` from its grain's centre of mass in the
/// grain's own frame; `position` and `arm` (the offset turned into the scene's frame) follow
/// the grain at every place(). A spherical grain is one sphere at offset 0: its sphere's
/// position is the grain's to the bit.
struct SphereSet {
    std::vector<std::uint64_t> id;
    std::vector<Index> grain;
    std::vector<double> radius;
    std::vector<Vec3> offset;
    std::vector<Vec3> position;
    std::vector<Vec3> arm;
    std::vector<int> contacts;
    /// Each sphere's springs, sorted by partner.
    std::vector<std::vector<Spring>> springs;
    std::uint64_t next_id = 0;

    Index size() const { return static_cast<Index>(id.size()); }
    void add(Index owner, double sphere_radius, const Vec3& own_offset);
    /// Positions and arms from the grains' positions and orientations.
    void place(const GrainSet& grains);
    /// Keep the spheres of the grains kept (grain_gone[g] == 0), their owners renumbered by
    /// new_index (old grain index -> new).
    void keep(std::span<const char> grain_gone, std::span<const Index> new_index);
    /// first[g] .. first[g + 1]: the spheres of grain g, for `grains` grains.
    void first_of_grains(Index grains, std::vector<Index>& first) const;
};

} // namespace grainload::dem
