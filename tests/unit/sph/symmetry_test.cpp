#include "sph/rates.hpp"
#include "sph/symmetry.hpp"

#include <array>
#include <gtest/gtest.h>

namespace grainload::sph {
namespace {

// The references here are built independently of sph/symmetry.cpp: the reflection as the matrix
// R = I - 2 n n^T (products of them for images of images), and the mirrored fields from how a
// field transforms under x' = R x: v'(x') = R v(x), so the velocity gradient of the image is
// L' = R L R^T; stress, strain rate and spin then follow from L' (or sigma' = R sigma R^T) with
// the solver's own conversions (rates.hpp), not from sign rules.
// Exact in floating point: R holds only 0 and +-1, so every product is exact up to the order of
// additions of terms of which all but one are exact zeros.
constexpr double kExact = 1e-15;

Mat3 reflection(MirrorMask mask) {
    Mat3 r = Mat3::Identity();
    for (int a = 0; a < 3; ++a) {
        if ((mask >> a) & 1U) {
            const Vec3 n = Vec3::Unit(a);
            r = (Mat3::Identity() - 2.0 * n * n.transpose()) * r;
        }
    }
    return r;
}

/// A velocity gradient with every entry distinct and non-zero, so that each sign shows.
Mat3 sample_gradient() {
    Mat3 l;
    l << 0.3, -1.7, 2.9, 0.8, -0.4, 1.3, -2.2, 0.6, 0.9;
    return l;
}

Voigt6 engineering_strain_rate(const Mat3& l) {
    const Mat3 d = 0.5 * (l + l.transpose());
    Voigt6 e;
    e << d(0, 0), d(1, 1), d(2, 2), 2.0 * d(0, 1), 2.0 * d(1, 2), 2.0 * d(2, 0);
    return e;
}

Vec3 spin_of(const Mat3& l) {
    const Mat3 w = 0.5 * (l - l.transpose());
    return {w(2, 1), w(0, 2), w(1, 0)};
}

TEST(Symmetry, MirroredKinematicsAreThoseOfTheMirroredVelocityField) {
    const Mat3 l = sample_gradient();
    for (unsigned mask = 1; mask < 8; ++mask) {
        const auto m = static_cast<MirrorMask>(mask);
        const Mat3 r = reflection(m);
        const Mat3 l_image = r * l * r.transpose();
        EXPECT_LT((mirror_tensor(engineering_strain_rate(l), m) - engineering_strain_rate(l_image))
                      .cwiseAbs()
                      .maxCoeff(),
                  kExact)
            << "mask " << mask;
        EXPECT_LT((mirror_axial(spin_of(l), m) - spin_of(l_image)).cwiseAbs().maxCoeff(), kExact)
            << "mask " << mask;
        // The spin is an axial vector: it is not mirrored like a velocity (a plane x = 0
        // keeps w_x and flips w_y and w_z, where a velocity flips v_x only).
        if (mask == 1) {
            EXPECT_GT((mirror_vector(spin_of(l), m) - spin_of(l_image)).norm(), 1.0);
        }
    }
}

TEST(Symmetry, MirroredStressVelocityAndPositionFollowTheReflection) {
    Voigt6 sigma;
    sigma << -3.0, -2.0, -1.5, 0.7, -0.4, 0.25;
    const Vec3 v(0.4, -1.1, 2.3);
    const Vec3 at(0.1, -0.2, 0.3);
    const Vec3 x(0.15, -0.17, 0.31);
    for (unsigned mask = 1; mask < 8; ++mask) {
        const auto m = static_cast<MirrorMask>(mask);
        const Mat3 r = reflection(m);
        const Mat3 expected_stress = r * stress_tensor(sigma) * r.transpose();
        EXPECT_LT((stress_tensor(mirror_tensor(sigma, m)) - expected_stress).cwiseAbs().maxCoeff(),
                  kExact)
            << "mask " << mask;
        EXPECT_LT((mirror_vector(v, m) - r * v).cwiseAbs().maxCoeff(), kExact);
        // x' = at + R (x - at): the image lies as far behind each plane as x before it.
        EXPECT_LT((mirror_position(x, m, at) - (at + r * (x - at))).cwiseAbs().maxCoeff(), 1e-15);
        const Mat3 c = sample_gradient();
        EXPECT_LT((mirror_matrix(c, m) - r * c * r.transpose()).cwiseAbs().maxCoeff(), kExact);
    }
    // The shear of a plane x = 0 in a pure xy shear flips; the normal stresses do not.
    const Voigt6 image = mirror_tensor(sigma, 1);
    EXPECT_EQ(image[3], -sigma[3]);
    EXPECT_EQ(image[4], sigma[4]);
    EXPECT_EQ(image[5], -sigma[5]);
    EXPECT_EQ(image[0], sigma[0]);
}

TEST(Symmetry, ParticlesNearAnEdgeGetThreeImagesAndWallsOnlyAcrossTheirPlanes) {
    const std::array<SymmetryPlane, 2> planes{SymmetryPlane{0, 0.0, 1}, SymmetryPlane{1, 0.0, 1}};
    const double cutoff = 0.1;
    // near the edge, near x = 0 only, far from both, a wall particle near the edge mirrored
    // across neither plane, one mirrored across x only, one on the plane x = 0 mirrored across
    // both (no image across x: it would coincide with it)
    const std::vector<Vec3> x{{0.05, 0.05, 0.0}, {0.05, 0.5, 0.0},  {0.5, 0.5, 0.0},
                              {0.02, 0.02, 0.0}, {0.02, 0.02, 0.0}, {0.0, 0.03, 0.0}};
    const std::vector<char> wall{0, 0, 0, 1, 1, 1};
    const std::vector<MirrorMask> allowed{7, 7, 7, 0, 1, 3};
    const auto images = select_images(planes, {}, x, wall, allowed, cutoff);
    ASSERT_EQ(images.size(), 6U);
    // the wall particles' images first: source 4 across x, source 5 across y
    EXPECT_EQ(images[0].source, 4);
    EXPECT_EQ(images[0].mask, 1);
    EXPECT_EQ(images[1].source, 5);
    EXPECT_EQ(images[1].mask, 2);
    int of_edge_particle = 0;
    for (std::size_t k = 2; k < images.size(); ++k) {
        EXPECT_LT(images[k].source, 2);
        of_edge_particle += images[k].source == 0;
        if (images[k].source == 1) {
            EXPECT_EQ(images[k].mask, 1);
        }
    }
    EXPECT_EQ(of_edge_particle, 3);
}

TEST(Symmetry, ImagesCopyScalarsAndMirrorFieldsAndAreDroppedAgain) {
    ParticleSet p;
    p.add(Vec3(0.01, 0.2, 0.0), Vec3(-0.3, 0.1, 0.0), 2.0, 1500.0, 0, 0, 1);
    p.stress[0] << -1.0, -2.0, 0.0, 0.5, 0.0, 0.0;
    p.spin[0] = Vec3(0.0, 0.0, 0.7);
    p.internal_energy[0] = 3.0;
    const std::vector<GhostImage> images{{0, 1}};
    write_images(p, 1, images, ImageFrame{});
    ASSERT_EQ(p.size(), 2);
    EXPECT_DOUBLE_EQ(p.position[1].x(), -0.01);
    EXPECT_DOUBLE_EQ(p.velocity[1].x(), 0.3);
    EXPECT_DOUBLE_EQ(p.velocity[1].y(), 0.1);
    EXPECT_DOUBLE_EQ(p.stress[1][3], -0.5);
    EXPECT_DOUBLE_EQ(p.spin[1].z(), -0.7); // a rotation about z turns the other way
    EXPECT_DOUBLE_EQ(p.mass[1], 2.0);
    EXPECT_DOUBLE_EQ(p.density[1], 1500.0);
    EXPECT_DOUBLE_EQ(p.internal_energy[1], 3.0);
    EXPECT_EQ(p.wall_id[1], -1);
    drop_images(p, 1);
    EXPECT_EQ(p.size(), 1);
    EXPECT_EQ(p.stress.size(), 1U);
}

} // namespace
} // namespace grainload::sph
