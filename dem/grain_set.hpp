#pragma once
// The DEM's particles: spheres as named per-grain fields, each with an identity of its own.

#include "io/types.hpp"
#include "particles/particle_view.hpp"

#include <Eigen/Geometry>
#include <cstdint>
#include <span>
#include <vector>

namespace grainload::dem {

/// One tangential spring a grain keeps with a partner: another grain (its id) or a wall
/// (kWallPartner + the wall's index). Kept by the grain of the lower id of a pair, so that a
/// grain's contacts travel with it wherever it goes (another rank, a compacted set).
struct Spring {
    std::uint64_t partner = 0;
    Vec3 shear = Vec3::Zero();
};
inline constexpr std::uint64_t kWallPartner = std::uint64_t{1} << 63;

/// Spheres in structure-of-arrays form, one entry per grain in every field. `id` is given at
/// creation and never reused: the key of contact histories, stable when grains leave and the
/// set is compacted (compaction keeps the order, so index order is id order).
struct GrainSet {
    std::vector<std::uint64_t> id;
    std::vector<int> body_id;
    std::vector<double> radius;
    std::vector<double> mass;
    std::vector<double> inertia; ///< 2/5 m r^2; 0 for a grain whose body does not rotate
    std::vector<Vec3> position;
    std::vector<Vec3> velocity;
    std::vector<Vec3> angular_velocity;
    std::vector<Eigen::Quaterniond> orientation;
    std::vector<Vec3> force;  ///< contacts and gravity at the last evaluation
    std::vector<Vec3> torque; ///< about the centre, at the last evaluation
    std::vector<int> contacts;
    /// Each grain's springs, sorted by partner.
    std::vector<std::vector<Spring>> springs;
    std::uint64_t next_id = 0;

    Index size() const { return static_cast<Index>(id.size()); }
    /// Append a sphere at rest in its orientation of reference.
    void add(int body, double grain_radius, double density, const Vec3& at, bool rotates);
    /// Keep the grains whose `gone` flag is 0, in order, in every field.
    void keep(std::span<const char> gone);
    /// The common fields the scene parts read.
    particles::ParticleView view() const { return {position, mass, body_id, {}}; }
};

} // namespace grainload::dem
