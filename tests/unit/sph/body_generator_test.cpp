#include "io/case_error.hpp"
#include "io/case_table.hpp"
#include "sph/body_shape_reader.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <numbers>

namespace grainload::sph {
namespace {

constexpr double kPi = std::numbers::pi;

Vec3 centroid(const std::vector<Vec3>& points) {
    Vec3 sum = Vec3::Zero();
    for (const Vec3& x : points) {
        sum += x;
    }
    return sum / static_cast<double>(points.size());
}

// Each particle stands for one lattice cell, so N dx^d is the discrete volume. The cells cut
// by the curved surface count whole or not at all; their errors largely cancel (lattice points
// in a circle), leaving well under 1 % at R / dx = 20 (measured: see the messages).
TEST(BodyGenerator, DiscAreaMatchesPiRSquared) {
    const double dx = 0.05;
    const double radius = 20 * dx;
    const auto points = fill_disc(Vec3(0.3, -0.2, 0.0), radius, dx, 2);
    const double area = static_cast<double>(points.size()) * dx * dx;
    std::cout << "disc R/dx = 20: area ratio " << area / (kPi * radius * radius) << '\n';
    EXPECT_NEAR(area / (kPi * radius * radius), 1.0, 0.01);
    const Vec3 c = centroid(points);
    EXPECT_NEAR(c.x(), 0.3, 1e-12);
    EXPECT_NEAR(c.y(), -0.2, 1e-12);
}

TEST(BodyGenerator, CylinderVolumeAndCentroidOnTheAxis) {
    const double dx = 0.001;
    const double radius = 20 * dx;
    const double height = 10 * dx;
    const Vec3 base(0.01, 0.02, -0.005);
    const auto points = fill_cone(base, Vec3(0.0, 0.0, 2.0), radius, radius, height, dx, 3);
    const double volume = static_cast<double>(points.size()) * dx * dx * dx;
    const double exact = kPi * radius * radius * height;
    std::cout << "cylinder R/dx = 20: volume ratio " << volume / exact << '\n';
    EXPECT_NEAR(volume / exact, 1.0, 0.02);
    const Vec3 c = centroid(points);
    EXPECT_NEAR(c.x(), base.x(), 1e-12);
    EXPECT_NEAR(c.y(), base.y(), 1e-12);
    EXPECT_NEAR(c.z(), base.z() + 0.5 * height, 1e-12);
}

TEST(BodyGenerator, ConeAndFrustumVolumes) {
    const double dx = 0.001;
    const double radius = 20 * dx;
    const double height = 40 * dx;
    const Vec3 base = Vec3::Zero();
    const auto cone = fill_cone(base, Vec3(1.0, 0.0, 0.0), radius, 0.0, height, dx, 3);
    const double cone_volume = static_cast<double>(cone.size()) * std::pow(dx, 3);
    const double cone_ratio = cone_volume / (kPi * radius * radius * height / 3.0);
    std::cout << "cone R/dx = 20, H/dx = 40: volume ratio " << cone_ratio << '\n';
    EXPECT_NEAR(cone_ratio, 1.0, 0.02);
    const Vec3 c = centroid(cone);
    EXPECT_NEAR(c.y(), 0.0, 1e-12);
    EXPECT_NEAR(c.z(), 0.0, 1e-12);
    EXPECT_NEAR(c.x(), 0.25 * height, 0.02 * height); // centroid of a cone: H / 4 from the base

    const double top = 0.5 * radius;
    const auto frustum = fill_cone(base, Vec3(0.0, 1.0, 0.0), radius, top, height, dx, 3);
    const double exact = kPi * height * (radius * radius + radius * top + top * top) / 3.0;
    EXPECT_NEAR(static_cast<double>(frustum.size()) * std::pow(dx, 3) / exact, 1.0, 0.02);

    // Plane strain: the section through the axis, a trapezoid of area H (R_base + R_top).
    const auto section = fill_cone(base, Vec3(0.0, 1.0, 0.0), radius, top, height, dx, 2);
    EXPECT_NEAR(static_cast<double>(section.size()) * dx * dx / (height * (radius + top)), 1.0,
                0.02);
}

TEST(BodyGenerator, JitterIsReproducibleAndStaysInItsCell) {
    const double dx = 0.01;
    const auto regular = fill_box(Vec3::Zero(), Vec3(0.2, 0.1, 0.0), dx, 2);
    auto first = regular;
    auto second = regular;
    auto other = regular;
    jitter_points(first, dx, 0.3, 42, 2);
    jitter_points(second, dx, 0.3, 42, 2);
    jitter_points(other, dx, 0.3, 43, 2);
    bool moved = false;
    bool differs = false;
    for (std::size_t k = 0; k < regular.size(); ++k) {
        EXPECT_EQ(first[k], second[k]);
        const Vec3 offset = first[k] - regular[k];
        EXPECT_LE(offset.cwiseAbs().maxCoeff(), 0.3 * dx);
        EXPECT_EQ(first[k].z(), 0.0);
        moved = moved || offset.norm() > 0.01 * dx;
        differs = differs || other[k] != first[k];
    }
    EXPECT_TRUE(moved);
    EXPECT_TRUE(differs);
}

TEST(BodyGenerator, CaseShapesAndLatticeKeys) {
    const auto document = io::CaseDocument::from_string(R"(
[cylinder]
type = "cylinder"
base = "0 0 0 mm"
axis = "0 0 1"
radius = "10 mm"
height = "5 mm"
lattice = "jittered"
jitter = 0.2
seed = 7
[cone]
type = "cone"
base = "0 0 0 mm"
axis = "0 0 1"
base_radius = "10 mm"
height = "10 mm"
[disc]
type = "cylinder"
centre = "0 0 0 mm"
radius = "10 mm"
[bad]
type = "cone"
base = "0 0 0 mm"
axis = "0 0 1"
base_radius = "10 mm"
height = "10 mm"
lattice = "jittered"
jitter = 0.7
)",
                                                        "shapes.toml");
    auto root = document->root();
    const double dx = 0.25e-3; // R / dx = 40
    const auto cylinder = generate_body_points(root.table("cylinder"), dx, 3, 1000.0);
    EXPECT_EQ(cylinder, generate_body_points(root.table("cylinder"), dx, 3, 1000.0));
    EXPECT_NEAR(static_cast<double>(cylinder.size()) * std::pow(dx, 3) / (kPi * 1e-4 * 5e-3), 1.0,
                0.02);
    const auto cone = generate_body_points(root.table("cone"), dx, 3, 1000.0);
    EXPECT_NEAR(static_cast<double>(cone.size()) * std::pow(dx, 3) / (kPi * 1e-4 * 1e-2 / 3.0), 1.0,
                0.02);
    const auto disc = generate_body_points(root.table("disc"), dx, 2, 1000.0);
    EXPECT_NEAR(static_cast<double>(disc.size()) * dx * dx / (kPi * 1e-4), 1.0, 0.01);
    EXPECT_THROW(generate_body_points(root.table("bad"), dx, 3, 1000.0), io::CaseError);
}

// A cube of n^3 cells cut by the plane x + y = L (normal (1, 1, 0), towards the kept side)
// keeps the cells whose centres (i + 1/2, j + 1/2) s satisfy i + j + 1 >= n: n (n + 1) / 2 per
// layer, counted here without the generator. With an offset of one cell diagonal, s sqrt(2),
// the kept centres satisfy i + j + 1 >= n + 2: (n - 1)(n - 2) / 2 per layer. A cut that keeps
// nothing, or has no normal, is an input error.
TEST(BodyGenerator, ShapesCutByPlanesKeepTheSideTheNormalPointsTo) {
    const auto document = io::CaseDocument::from_string(R"(
[cut]
type = "box"
min = "0 0 0 m"
max = "1 1 1 m"
[[cut.cut]]
point = "1 0 0 m"
normal = "1 1 0"
[offset]
type = "box"
min = "0 0 0 m"
max = "1 1 1 m"
[[offset.cut]]
point = "1 0 0 m"
normal = "1 1 0"
offset = "0.141421356237309 m"
[empty]
type = "box"
min = "0 0 0 m"
max = "1 1 1 m"
[[empty.cut]]
point = "3 0 0 m"
normal = "1 0 0"
)",
                                                        "cuts.toml");
    auto root = document->root();
    constexpr int n = 10;
    const double s = 0.1;
    const auto cut = generate_body_points(root.table("cut"), s, 3, 1000.0);
    EXPECT_EQ(cut.size(), static_cast<std::size_t>(n * n * (n + 1) / 2));
    for (const Vec3& x : cut) {
        EXPECT_GE(x.x() + x.y(), 1.0);
    }
    const auto offset = generate_body_points(root.table("offset"), s, 3, 1000.0);
    EXPECT_EQ(offset.size(), static_cast<std::size_t>(n * (n - 1) * (n - 2) / 2));
    EXPECT_THROW(generate_body_points(root.table("empty"), s, 3, 1000.0), io::CaseError);
}

// A layer two particles thick is named with its axis and count; three across (the kernel
// support of h = 1.3 dp filled from the middle row) passes; in plane strain z is not an axis.
TEST(BodyGenerator, ThinBodiesAreWarnedAbout) {
    const double dx = 0.01;
    std::vector<Vec3> slab;
    for (int i = 0; i < 10; ++i) {
        for (int j = 0; j < 10; ++j) {
            for (int k = 0; k < 2; ++k) {
                slab.emplace_back(i * dx, j * dx, k * dx);
            }
        }
    }
    const std::string warning = thin_body_warning(slab, dx, 3, "layer");
    EXPECT_NE(warning.find("body \"layer\" is 2 particles across along z"), std::string::npos)
        << warning;
    for (int i = 0; i < 10; ++i) {
        for (int j = 0; j < 10; ++j) {
            slab.emplace_back(i * dx, j * dx, 2 * dx);
        }
    }
    EXPECT_EQ(thin_body_warning(slab, dx, 3, "layer"), "");
    std::vector<Vec3> strip;
    for (int i = 0; i < 10; ++i) {
        for (int j = 0; j < 3; ++j) {
            strip.emplace_back(i * dx, j * dx, 0.0);
        }
    }
    EXPECT_EQ(thin_body_warning(strip, dx, 2, "strip"), "");
    EXPECT_NE(thin_body_warning(strip, dx, 3, "strip").find("1 particle across along z"),
              std::string::npos);
}

// A cylinder of 40 mm diameter and height at 3 mm, its base centre on a cell corner: the cells
// whose centres lie inside stack 13 high (the 14th centre, 40.5 mm, is above the top), 39 mm,
// and reach 7 cells each side of the axis (19.5 mm, sqrt(19.5^2 + 1.5^2) = 19.56 mm < 20 mm),
// 42 mm across: the lattice rounds every size, and says so. A box whose edges are whole
// spacings is filled exactly (no entry), one 100 mm long at 30 mm is 3 cells, 90 mm; a shape
// cut by planes or jittered states no drawn size to compare with, or is compared before the
// jitter.
TEST(BodyGenerator, TheLatticeSaysWhereItRoundsTheDrawnSize) {
    const auto document = io::CaseDocument::from_string(R"(
[cylinder]
type = "cylinder"
base = "0 0 0 mm"
axis = "0 0 1"
radius = "20 mm"
height = "40 mm"
[jittered]
type = "cylinder"
base = "0 0 0 mm"
axis = "0 0 1"
radius = "20 mm"
height = "40 mm"
lattice = "jittered"
jitter = 0.4
[box]
type = "box"
min = "0 0 0 mm"
max = "30 60 90 mm"
[long]
type = "box"
min = "0 0 0 mm"
max = "100 30 30 mm"
[cut]
type = "box"
min = "0 0 0 mm"
max = "100 30 30 mm"
[[cut.cut]]
point = "0 0 0 m"
normal = "1 0 0"
)",
                                                        "rounding.toml");
    auto root = document->root();
    const double s = 3e-3;
    auto rounded = [&](const char* shape, double spacing) {
        std::vector<RoundedSize> sizes;
        generate_body_points(root.table(shape), spacing, 3, 1000.0, &sizes);
        return sizes;
    };
    const auto cylinder = rounded("cylinder", s);
    ASSERT_EQ(cylinder.size(), 3u);
    for (int a = 0; a < 3; ++a) {
        EXPECT_EQ(cylinder[static_cast<std::size_t>(a)].axis, a);
        EXPECT_NEAR(cylinder[static_cast<std::size_t>(a)].drawn, 0.040, 1e-15);
        EXPECT_NEAR(cylinder[static_cast<std::size_t>(a)].filled, a < 2 ? 0.042 : 0.039, 1e-15);
    }
    const auto jittered = rounded("jittered", s);
    ASSERT_EQ(jittered.size(), 3u);
    EXPECT_NEAR(jittered[2].filled, 0.039, 1e-15);
    EXPECT_TRUE(rounded("box", 0.03).empty());
    const auto long_box = rounded("long", 0.03);
    ASSERT_EQ(long_box.size(), 1u);
    EXPECT_EQ(long_box[0].axis, 0);
    EXPECT_NEAR(long_box[0].drawn, 0.1, 1e-15);
    EXPECT_NEAR(long_box[0].filled, 0.09, 1e-15);
    EXPECT_TRUE(rounded("cut", 0.03).empty());
}

} // namespace
} // namespace grainload::sph
