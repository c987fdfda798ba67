#pragma once
// Planes of mirror symmetry, whose ghost particles stand for the material beyond them.

#include "io/key_spec.hpp"
#include "sph/particle_set.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace grainload::sph {

/// The keys of each [[sph.symmetry]] table (docs/user-guide/sph.md, "Symmetry planes").
inline constexpr std::array<io::KeySpec, 3> kSymmetryKeys{{
    {"axis", "`x`, `y` or `z`", "",
     "the plane's normal: a coordinate axis (z only in 3D; at most one plane per axis)"},
    {"at", "length", "0 m", "the plane's coordinate on that axis", 0.0},
    {"side", "`+` or `-`", "the bodies' side",
     "which side holds the material; every body must lie on it"},
}};

/// A plane of mirror symmetry, normal to a coordinate axis: the material lies on one side and
/// sees its mirror image on the other ([[sph.symmetry]], docs/user-guide/sph.md).
struct SymmetryPlane {
    int axis = 0;    ///< 0, 1, 2: the plane is x_axis = at
    double at = 0.0; ///< m
    int side = 1;    ///< +1: the material lies at x_axis > at; -1: below
};

/// Which axes an image is reflected across: bit a set for a reflection across the plane normal
/// to axis a. One plane gives images with one bit; two planes meeting at an edge add the image of
/// the image (both bits), three at a corner all seven combinations.
using MirrorMask = std::uint8_t;

/// The ghost (mirror) particle of a source particle (Libersky et al. 1993).
struct MirrorImage {
    Index source = 0;
    MirrorMask mask = 0;
};

/// The reflection R = I - 2 n n^T of the planes in `mask` (n a coordinate axis each, so R is
/// diagonal): sign(mask)[a] = -1 for a reflected axis, +1 otherwise.
Vec3 mirror_signs(MirrorMask mask);
/// x' = R x + (I - R) x_plane: coordinate a of a reflected axis becomes 2 at_a - x_a.
Vec3 mirror_position(const Vec3& x, MirrorMask mask, const Vec3& plane_at);
/// A polar vector (velocity, acceleration): v' = R v.
Vec3 mirror_vector(const Vec3& v, MirrorMask mask);
/// An axial vector (the spin's): w' = det(R) R w.
Vec3 mirror_axial(const Vec3& w, MirrorMask mask);
/// A symmetric tensor in Voigt order xx yy zz xy yz zx (stress, or strain rate with engineering
/// shear): T' = R T R, so T'_ab = s_a s_b T_ab: the shears that involve exactly one reflected
/// axis change sign.
Voigt6 mirror_tensor(const Voigt6& t, MirrorMask mask);
/// A general 3x3 tensor (the gradient correction): M' = R M R.
Mat3 mirror_matrix(const Mat3& m, MirrorMask mask);

/// The images the planes need at a neighbour-list build: every non-empty combination of planes
/// for each particle within `cutoff` of all the planes of the combination, across the planes in
/// its `allowed` mask only (material particles: all; walls: those they are mirrored across, see
/// Wall::mirror_planes). A particle on a plane (closer than 1e-9 cutoff: a wall lattice point)
/// has no image across it, which would coincide with it. Wall particles' images come first,
/// then sorted by mask and source, so the order depends only on the positions.
std::vector<MirrorImage> select_images(std::span<const SymmetryPlane> planes,
                                       std::span<const Vec3> positions,
                                       std::span<const char> is_wall,
                                       std::span<const MirrorMask> allowed, double cutoff);

/// The planes' coordinates as a vector (at of the plane normal to axis a in component a; 0 for
/// an axis without a plane).
Vec3 plane_coordinates(std::span<const SymmetryPlane> planes);

/// Resize every particle field to `real_count + images.size()` and set particle real_count + k
/// to the mirror image of images[k].source, each field by the Mirror rule it is registered
/// with (sph/particle_set.hpp): position reflected, velocity and acceleration mirrored as polar
/// vectors, stress and strain rate as tensors, spin as an axial vector; mass, density and its
/// rate, energies, plastic strain, body, material, wall and state offset copied. Ghosts are
/// never clamped. Parallel over the images.
void write_images(ParticleSet& particles, Index real_count, std::span<const MirrorImage> images,
                  const Vec3& plane_at);

/// Drop every field back to the first `real_count` particles (capacity kept).
void drop_images(ParticleSet& particles, Index real_count);

} // namespace grainload::sph
