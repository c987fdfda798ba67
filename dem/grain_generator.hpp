#pragma once
// Grains placed at random in a box, none overlapping another: a loose packing to settle.

#include "dem/dem_case_reader.hpp"
#include "dem/grain_set.hpp"
#include "dem/sphere_set.hpp"

#include <numbers>
#include <random>
#include <vector>

namespace grainload::dem {

/// The mass of a sphere of `radius` and `density`, 4/3 pi r^3 rho.
inline double sphere_mass(double radius, double density) {
    return 4.0 / 3.0 * std::numbers::pi * radius * radius * radius * density;
}

/// One grain of a body as its spheres make it: `spheres` equal spheres of radius r on the
/// grain's own x axis, centre to centre sphere_distance x 2r (1: touching, as the paper's
/// two-sphere particles; Markauskas), the centre of mass at their middle. Mass k m_s; principal
/// moments k (2/5) m_s r^2 about the axis and sum((2/5) m_s r^2 + m_s x_j^2) across it. A clump
/// of any shape (sphere_centres, of equal or unequal spheres: sphere_radii) in its principal
/// frame, its moments the inertia tensor's eigenvalues in ascending order (grain_generator.cpp,
/// clump_shape). `radius` is the grain's drawn radius r, `radii` each sphere's.
struct GrainShape {
    double radius = 0.0;
    double mass = 0.0;
    Vec3 inertia = Vec3::Zero();
    std::vector<Vec3> offsets;
    std::vector<double> radii;
};
GrainShape grain_shape(const BodySettings& body, double radius, double density);

/// Uniform in [0, 1) from 53 bits of the generator, the same on every standard library.
double uniform(std::mt19937_64& generator);
/// A uniformly random orientation (Shoemake 1992, "Uniform random rotations").
Eigen::Quaterniond random_orientation(std::mt19937_64& generator);
/// How far a grain of `shape`, turned by `turned`, reaches from its centre along each axis.
Vec3 grain_reach(const GrainShape& shape, const Eigen::Quaterniond& turned);
/// A grain's radius, uniform in [radius_min, radius_max] (Lazarevic et al. 2002, eq. 1).
double draw_radius(const BodySettings& body, std::mt19937_64& generator);

/// Append one grain of `body` (id `body_id`) of `shape` at `centre`, turned by `turned`, with
/// its velocities (none turning where the body does not rotate), and its spheres; returns its
/// index. The spheres' positions follow at the next SphereSet::place.
Index add_grain(const BodySettings& body, int body_id, const GrainShape& shape, const Vec3& centre,
                const Eigen::Quaterniond& turned, const Vec3& velocity,
                const Vec3& angular_velocity, GrainSet& grains, SphereSet& spheres);

/// Append the grains of `body` (id `body_id`, solid density `density`) and their spheres: one
/// at its centre, its axis along `axis`, or `count` by random sequential addition in its box
/// (Widom 1966): each grain's radius drawn uniformly in [radius_min, radius_max] as in
/// Lazarevic et al. (2002, eq. 1), its centre uniformly where every sphere lies wholly inside the
/// box whatever its orientation, a clump's orientation uniformly at random (a sphere's is the
/// identity), kept when none of its spheres overlaps a sphere placed before (of any body),
/// else drawn again (the radius kept, so that the sizes follow their distribution; ten
/// thousand draws of the centre before the box is called full). A loose packing that gravity
/// then settles. The draws follow a 64-bit Mersenne twister seeded by `seed`: equal seeds give
/// equal packings on every machine. Throws io::CaseError naming the body's count when the box
/// cannot hold it.
void place_grains(const BodySettings& body, int body_id, double density, GrainSet& grains,
                  SphereSet& spheres);

} // namespace grainload::dem
