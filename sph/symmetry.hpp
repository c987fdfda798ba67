#pragma once
// Planes of mirror symmetry and periodic directions, whose ghost particles stand for the
// material beyond them.

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

/// The keys of each [[sph.periodic]] table (docs/user-guide/sph.md, "Periodic directions").
inline constexpr std::array<io::KeySpec, 3> kPeriodicKeys{{
    {"axis", "`x`, `y` or `z`", "",
     "the periodic direction: a coordinate axis (z only in 3D; not one with a symmetry plane)"},
    {"min", "length", "", "the lower end of the period along that axis"},
    {"max", "length", "", "the upper end: what leaves past max comes back at min, and back"},
}};

/// A plane of mirror symmetry, normal to a coordinate axis: the material lies on one side and
/// sees its mirror image on the other ([[sph.symmetry]], docs/user-guide/sph.md).
struct SymmetryPlane {
    int axis = 0;    ///< 0, 1, 2: the plane is x_axis = at
    double at = 0.0; ///< m
    int side = 1;    ///< +1: the material lies at x_axis > at; -1: below
};

/// A periodic direction: the scene repeats along `axis` with the period max - min, so that a
/// particle leaving past max comes back at min and the particles near one end see those near
/// the other ([[sph.periodic]], docs/user-guide/sph.md).
struct PeriodicAxis {
    int axis = 0;     ///< 0, 1, 2
    double min = 0.0; ///< m
    double max = 0.0; ///< m
    double period() const { return max - min; }
};

/// Which axes an image is reflected across: bit a set for a reflection across the plane normal
/// to axis a. One plane gives images with one bit; two planes meeting at an edge add the image of
/// the image (both bits), three at a corner all seven combinations.
using MirrorMask = std::uint8_t;

/// The ghost particle of a source particle: its mirror image across symmetry planes (Libersky et
/// al. 1993), its periodic image one period along periodic axes, or both.
struct GhostImage {
    Index source = 0;
    MirrorMask mask = 0;       ///< axes reflected across their symmetry plane
    MirrorMask shift_up = 0;   ///< periodic axes along which the image lies one period above
    MirrorMask shift_down = 0; ///< periodic axes along which it lies one period below
};

/// Where images stand: the symmetry planes' coordinates and the periods (each in the component
/// of its axis; 0 for an axis without one).
struct ImageFrame {
    Vec3 plane_at = Vec3::Zero();
    Vec3 period = Vec3::Zero();
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

/// The position of an image: reflected across the planes of its mask, then shifted by a period
/// along the axes of its shifts.
Vec3 image_position(const Vec3& x, const GhostImage& image, const ImageFrame& frame);

/// The images the planes and periodic axes need at a neighbour-list build. A particle is near a
/// plane within `cutoff` of it (a particle on a plane, closer than 1e-9 cutoff: a wall lattice
/// point, has no image across it, which would coincide with it), and near a periodic axis
/// within `cutoff` of either end (its image then lies a period beyond the other end; the period
/// must exceed 2 cutoff, so that no particle is near both). It gets one image for every
/// non-empty combination of the axes it is near: every periodic axis, and the symmetry planes
/// in its `allowed` mask only (material particles: all; walls: the planes they are mirrored
/// across, Wall::mirror_planes). Wall particles' images come first, then sorted by the
/// combination and the source, so the order depends only on the positions.
std::vector<GhostImage> select_images(std::span<const SymmetryPlane> planes,
                                      std::span<const PeriodicAxis> periodic,
                                      std::span<const Vec3> positions,
                                      std::span<const char> is_wall,
                                      std::span<const MirrorMask> allowed, double cutoff);

/// The planes' coordinates and the periods.
ImageFrame image_frame(std::span<const SymmetryPlane> planes,
                       std::span<const PeriodicAxis> periodic);

/// Bring the material particles that have left a periodic box back into it (x - period past
/// max, x + period before min); wall particles stay where their wall puts them.
void wrap_periodic(std::span<Vec3> positions, std::span<const char> is_wall,
                   std::span<const PeriodicAxis> periodic);

/// The nearest image of a separation `d` along the periodic axes (each component within half a
/// period): a displacement across the seam of a wrapped particle.
Vec3 nearest_image(Vec3 d, std::span<const PeriodicAxis> periodic);

/// Resize every particle field to `real_count + images.size()` and set particle real_count + k
/// to the image of images[k].source, each field by the Mirror rule it is registered
/// with (sph/particle_set.hpp): position by image_position(), velocity and acceleration mirrored as
/// polar vectors, stress and strain rate as tensors, spin as an axial vector (a shift alone keeps
/// them); mass, density and its rate, energies, plastic strain, body, material, wall and state
/// offset copied. Ghosts are never clamped. Parallel over the images.
void write_images(ParticleSet& particles, Index real_count, std::span<const GhostImage> images,
                  const ImageFrame& frame);

/// Drop every field back to the first `real_count` particles (capacity kept).
void drop_images(ParticleSet& particles, Index real_count);

} // namespace grainload::sph
