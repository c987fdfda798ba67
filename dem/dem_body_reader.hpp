#pragma once
// One [[dem.body]] as the case states it: its keys, its settings and their reader.

#include "io/key_spec.hpp"
#include "io/types.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace grainload::io {
class CaseTable;
}
namespace grainload::materials {
class MaterialLibrary;
}

namespace grainload::dem {

/// The keys of each [[dem.body]].
inline constexpr std::array<io::KeySpec, 18> kDemBodyKeys{{
    {"name", "string", "", "names the body in frames and summary.json"},
    {"material", "string", "",
     "a `linear_elastic` [[material]]: the solid grain's density, E and nu"},
    {"radius", "length", "required unless radius_min and radius_max", "every grain's radius"},
    {"radius_min", "length", "required unless radius",
     "radii drawn uniformly in [radius_min, radius_max]"},
    {"radius_max", "length", "required unless radius", "with radius_min"},
    {"count", "integer >= 1", "required with min and max", "grains placed at random in the box"},
    {"min", "length vector", "required unless centre or a source",
     "the lower corner of the box they fill"},
    {"max", "length vector", "required unless centre or a source", "the upper corner"},
    {"centre", "length vector", "none", "instead of a box: one grain with its centre here"},
    {"spheres", "integer in [1, 16]", "1",
     "spheres per grain: 2 or more make a rigid clump of equal spheres on one axis", 1.0},
    {"sphere_distance", "number >= 1", "1",
     "a clump's centre-to-centre distance of neighbouring spheres over their diameter (1: "
     "touching)",
     1.0},
    {"sphere_centres", "list of numbers", "none: `spheres` on one axis",
     "a clump of any shape: x y z of each sphere's centre in sphere radii, three numbers per "
     "sphere (2 to 16 spheres, no two overlapping)"},
    {"sphere_radii", "list of numbers", "1 for every sphere",
     "with sphere_centres: each sphere's radius in the grain's radius, one per centre, in "
     "[0.1, 10]"},
    {"axis", "vector", "1 0 0",
     "a clump placed at a centre: the direction of its axis (of least inertia)"},
    {"velocity", "velocity vector", "0 m/s", "every grain's initial velocity"},
    {"angular_velocity", "angular velocity vector", "0 rad/s",
     "every grain's initial angular velocity"},
    {"rotation", "boolean", "true", "false: the grains do not turn (no rotational freedom)", 1.0},
    {"seed", "integer >= 0", "1", "the random placement's seed: equal seeds, equal packings", 1.0},
}};

/// One [[dem.body]] as read.
struct BodySettings {
    std::string name;
    int material = -1;
    double radius_min = 0.0;
    double radius_max = 0.0;
    Index count = 1;
    Vec3 min = Vec3::Zero();
    Vec3 max = Vec3::Zero();
    std::optional<Vec3> centre;
    int spheres = 1;
    double sphere_distance = 1.0;
    /// A clump of any shape: its spheres' centres in sphere radii (empty: `spheres` on one
    /// axis, `sphere_distance` apart).
    std::vector<Vec3> sphere_centres;
    /// Each sphere's radius over the grain's drawn radius (empty: every sphere of it).
    std::vector<double> sphere_radii;
    Vec3 axis = Vec3::UnitX();
    Vec3 velocity = Vec3::Zero();
    Vec3 angular_velocity = Vec3::Zero();
    bool rotation = true;
    std::uint64_t seed = 1;
    /// Where the case gives the count (or the centre): a packing that cannot hold the count is
    /// refused there.
    std::string where;
    /// How far a grain reaches from its centre of mass, in the grain's radius: its farthest
    /// sphere's centre distance plus that sphere's radius, 1 + (spheres - 1) sphere_distance on
    /// one axis.
    double reach() const;
    /// The radius of its sphere k over the grain's radius (1 unless sphere_radii).
    double sphere_radius(std::size_t k) const {
        return sphere_radii.empty() ? 1.0 : sphere_radii[k];
    }
    /// Its largest and its smallest sphere's radius over the grain's radius.
    double largest_sphere() const;
    double smallest_sphere() const;
    /// The grain's volume over a sphere's of the grain's radius: the sum of its spheres' cubed
    /// radii (its sphere count for equal spheres).
    double volume_ratio() const;
};

/// Reads one [[dem.body]] table: radii, clump (spheres on an axis or sphere_centres), placement,
/// velocities; a bad key throws io::CaseError naming it.
BodySettings read_dem_body(const io::CaseTable& table, const materials::MaterialLibrary& materials);

} // namespace grainload::dem
