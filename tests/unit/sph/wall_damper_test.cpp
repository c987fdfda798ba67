#include "sph/wall_contact.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

/// The damping heat WallContact books for one grain touching one wall particle at x = 0 whose
/// wall normal is `normal`, the grain at `x` moving at `v` (3D, 100 mm spacing, the hopper
/// wagon's contact: 22.7 MPa, critical damping).
double damping_heat(const Vec3& normal, const Vec3& x, const Vec3& v) {
    constexpr double kSpacing = 0.1;
    const SmoothingKernel kernel(KernelType::cubic_spline, 1.3 * kSpacing, 3);
    SphOptions options;
    options.smoothing_length = kernel.smoothing_length();
    options.particle_spacing = kSpacing;
    options.contact = {22.7e6, 1.0, 1.0};
    ParticleSet particles;
    particles.add(x, v, 2099.0 * std::pow(kSpacing, 3), 2099.0, 0, 0, 0);
    std::vector<Wall> walls;
    walls.push_back(add_wall(particles, "wall", 0, 1, {Vec3::Zero()}, kSpacing, 1.0, 3));
    walls[0].normals = {normal};
    particles::NeighbourList neighbours(kernel.support_radius(), 0.0, 3);
    const std::vector<char> frozen{0, 1};
    neighbours.update(particles.position, frozen, true);
    std::vector<double> heating(2, 0.0);
    WallContact contact;
    contact.apply(particles, neighbours, kernel, options, walls, 1e-4, heating);
    return heating[0];
}

// The normal dashpot's stiffness is k_n = sum_j k_ij (e_ij . n)^2 (wall_contact.hpp), which
// vanishes for a grain in the plane of the wall particle it touches: a grain passing a wall's
// edge (a door post or sill) beside its particles. There the dashpot must do nothing, so the
// heat is zero. Evaluated as n . (sum_j k_ij e_ij e_ij^T) n, round-off left that form a few
// ulps of k_ij below zero for 21 of these 48 grains, and sqrt(k_n m) made the damper and the
// heat NaN: the force was dropped (a NaN force fails its |F|^2 > 0 test) and the grain's
// internal energy became NaN while every field the watchdog reads stayed finite, until a sink
// removed it and the energy books with it: the one path found by which a grain's energy alone
// turns NaN, as the elastic hopper wagon's removed_energy did (not reproduced there). A normal
// along an axis, as a rigid vertical wall's, forms one diagonal entry, a plain sum of squares
// (0 of 48 before the fix); tilted by 1e-4 rad, as an elastic shell's directors are, 3 of 48;
// tilted well off the axes, as here, 21 of 48. Grains at 8 angles about the normal,
// 10^-18 .. 10^-8 of their distance out of the wall's plane.
TEST(WallDamper, DoesNothingForAGrainInTheWallsPlane) {
    const Vec3 normal = Vec3(1.0, 2.0, 3.0).normalized();
    const Vec3 u = normal.cross(Vec3::UnitX()).normalized();
    const Vec3 w = normal.cross(u);
    const Vec3 v(0.3, -0.2, 0.5);
    // Reference: the grain straight above the particle at the same distance, where the whole
    // dashpot acts: what it heats is the scale for "nothing".
    const double r = 0.15;
    const double full = damping_heat(normal, r * normal, v);
    ASSERT_GT(full, 0.0);
    int non_finite = 0;
    double largest = 0.0;
    for (int k = 0; k < 8; ++k) {
        const double angle = 2.0 * M_PI * k / 8.0;
        const Vec3 in_plane = std::cos(angle) * u + std::sin(angle) * w;
        for (int decade = -18; decade <= -8; decade += 2) {
            const double h =
                damping_heat(normal, r * (in_plane + std::pow(10.0, decade) * normal), v);
            non_finite += std::isfinite(h) ? 0 : 1;
            largest = std::max(largest, std::abs(h));
        }
    }
    EXPECT_EQ(non_finite, 0) << "grains in the wall's plane booked a NaN damping heat";
    // Out of the plane by d = 10^-8 r at most: k_n is (d / r)^2 of the full k and the
    // repulsion's normal part d / r of the full one, so the damper, and with the same normal
    // speed the heat, is at most about 10^-8 of the full one (1e-7: the stiffnesses at the two
    // places differ by the kernel's slope, not by orders).
    EXPECT_LT(largest, 1e-7 * full);
}

} // namespace
} // namespace grainload::sph
