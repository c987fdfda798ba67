#include "sph/heap_measures.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <numbers>

namespace grainload::sph {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

/// Cell centres of a regular lattice of step dp (a cell corner at the origin, the floor z = 0)
/// inside a cone of base radius R and slope `angle` on the axis x = y = 0.
std::vector<Vec3> lattice_cone(double dp, double radius, double angle) {
    const double height = radius * std::tan(angle);
    const int n = static_cast<int>(std::ceil(radius / dp));
    std::vector<Vec3> x;
    for (int i = -n; i < n; ++i) {
        for (int j = -n; j < n; ++j) {
            for (int k = 0; (k + 0.5) * dp < height; ++k) {
                const Vec3 c((i + 0.5) * dp, (j + 0.5) * dp, (k + 0.5) * dp);
                if (c.z() < height * (1.0 - std::hypot(c.x(), c.y()) / radius)) {
                    x.push_back(c);
                }
            }
        }
    }
    return x;
}

/// Equal masses for the particles of `x`: the figures that weigh particles see a body of one
/// material on one lattice.
std::vector<double> unit_masses(const std::vector<Vec3>& x) {
    return std::vector<double>(x.size(), 1.0);
}

HeapFrame cone_frame(double dp) {
    HeapFrame frame;
    frame.spacing = dp;
    frame.up = Vec3::UnitZ();
    frame.dimension = 3;
    return frame;
}

// A lattice cone of 30 deg, R = 30 dp. A particle is a cube of side dp around its centre, so
// the lattice resolves the cone's apex, rim and surface to within one spacing: height and
// run-out to dp. Each bin's surface sample lies up to dp below the surface, at random over the
// bins, so the fitted slope over the 18 bins between 20 % and 80 % height errs by about
// dp / (18 dp) / sqrt(18) = 0.8 deg; 1.5 deg leaves room for the bins' correlation.
TEST(HeapMeasures, LatticeConeGivesItsHeightRadiusAndAngle) {
    const double dp = 0.01;
    const double radius = 30 * dp;
    const double angle = 30.0 * kDegree;
    const auto x = lattice_cone(dp, radius, angle);
    const HeapMeasures heap = measure_heap(x, unit_masses(x), cone_frame(dp));
    ASSERT_TRUE(heap.angle.has_value());
    std::cout << "cone: height " << heap.final_height / dp << " dp (exact "
              << radius * std::tan(angle) / dp << "), run-out " << heap.run_out / dp
              << " dp (30), angle " << *heap.angle / kDegree << " deg (30)\n";
    EXPECT_NEAR(heap.final_height, radius * std::tan(angle), dp);
    EXPECT_NEAR(heap.run_out, radius, dp);
    EXPECT_NEAR(*heap.angle, angle, 1.5 * kDegree);
    EXPECT_EQ(heap.heap_count, static_cast<Index>(x.size()));
    EXPECT_EQ(heap.outside_count, 0);
}

// The same cone turned: gravity along -x, the axis through a shifted origin. Only the frame
// changes, so every figure must be the same to round-off.
TEST(HeapMeasures, FiguresDoNotDependOnTheFrame) {
    const double dp = 0.01;
    const auto x = lattice_cone(dp, 20 * dp, 40.0 * kDegree);
    const Vec3 shift(0.3, -0.2, 0.1);
    std::vector<Vec3> turned;
    for (const Vec3& p : x) {
        turned.push_back(shift + Vec3(p.z(), p.x(), p.y())); // z -> x, x -> y, y -> z
    }
    HeapFrame frame = cone_frame(dp);
    const HeapMeasures upright = measure_heap(x, unit_masses(x), frame);
    frame.origin = shift;
    frame.up = Vec3::UnitX();
    const HeapMeasures lying = measure_heap(turned, unit_masses(turned), frame);
    EXPECT_NEAR(lying.final_height, upright.final_height, 1e-12);
    EXPECT_NEAR(lying.run_out, upright.run_out, 1e-12);
    ASSERT_TRUE(lying.angle && upright.angle);
    EXPECT_NEAR(*lying.angle, *upright.angle, 1e-9);
}

// Plane strain: a trapezoid against a back face at x = 0, height H = 20 dp, a flat top 10 dp
// wide, then a 40 deg slope to the floor. The flat top lies above 80 % of the height and is
// left out of the fit; the flank is exact up to the lattice's dp steps (tolerances as above).
TEST(HeapMeasures, PlaneStrainTrapezoid) {
    const double dp = 0.005;
    const double height = 20 * dp;
    const double top = 10 * dp;
    const double angle = 40.0 * kDegree;
    const double foot = top + height / std::tan(angle);
    std::vector<Vec3> x;
    for (int i = 0; (i + 0.5) * dp < foot; ++i) {
        for (int j = 0; (j + 0.5) * dp < height; ++j) {
            const Vec3 c((i + 0.5) * dp, (j + 0.5) * dp, 0.0);
            if (c.x() < top + (height - c.y()) / std::tan(angle)) {
                x.push_back(c);
            }
        }
    }
    HeapFrame frame;
    frame.spacing = dp;
    frame.up = Vec3::UnitY();
    frame.dimension = 2;
    const HeapMeasures heap = measure_heap(x, unit_masses(x), frame);
    ASSERT_TRUE(heap.angle.has_value());
    std::cout << "trapezoid: height " << heap.final_height / dp << " dp (20), run-out "
              << heap.run_out / dp << " dp (" << foot / dp << "), angle " << *heap.angle / kDegree
              << " deg (40)\n";
    EXPECT_NEAR(heap.final_height, height, 1e-12); // a whole number of layers: exact
    EXPECT_NEAR(heap.run_out, foot, dp);
    EXPECT_NEAR(*heap.angle, angle, 1.5 * kDegree);
}

// A particle 2 dp beyond the cone's rim is no part of the heap: it is counted outside and
// changes neither the run-out nor the height.
TEST(HeapMeasures, LoneParticleIsLeftOutsideTheHeap) {
    const double dp = 0.01;
    auto x = lattice_cone(dp, 15 * dp, 35.0 * kDegree);
    const HeapMeasures alone = measure_heap(x, unit_masses(x), cone_frame(dp));
    x.emplace_back(17.5 * dp, 0.5 * dp, 0.5 * dp);
    const HeapMeasures with_stray = measure_heap(x, unit_masses(x), cone_frame(dp));
    EXPECT_EQ(with_stray.outside_count, 1);
    EXPECT_EQ(with_stray.heap_count, alone.heap_count);
    EXPECT_DOUBLE_EQ(with_stray.run_out, alone.run_out);
    EXPECT_DOUBLE_EQ(with_stray.final_height, alone.final_height);
}

/// A plane-strain deposit `columns` wide and `rows` high against the back face x = 0 (cell
/// centres (i + 1/2, j + 1/2) dp), and a toe of `toe` particles on the floor in front of it,
/// the first `gap` (centre to centre) from the deposit's last column, then one every dp.
std::vector<Vec3> deposit_with_toe(double dp, int columns, int rows, int toe, double gap) {
    std::vector<Vec3> x;
    for (int i = 0; i < columns; ++i) {
        for (int j = 0; j < rows; ++j) {
            x.emplace_back((i + 0.5) * dp, (j + 0.5) * dp, 0.0);
        }
    }
    for (int k = 0; k < toe; ++k) {
        x.emplace_back((columns - 0.5) * dp + gap + k * dp, 0.5 * dp, 0.0);
    }
    return x;
}

HeapFrame plane_frame(double dp) {
    HeapFrame frame;
    frame.spacing = dp;
    frame.up = Vec3::UnitY();
    frame.dimension = 2;
    return frame;
}

// 150 columns of 4 equal particles: 99 % of the 600 is 594, which the first 149 columns (596)
// hold and 148 (592) do not, so the mass-based run-out is the 149th column's far edge,
// 149 dp, exactly up to the round-off of the lattice's coordinates; the cluster's edge is the
// last column's, 150 dp.
TEST(HeapMeasures, MassRunOutIsTheDistanceHoldingNinetyNinePercentOfTheMass) {
    const double dp = 0.01;
    const auto x = deposit_with_toe(dp, 150, 4, 0, 0.0);
    const HeapMeasures heap = measure_heap(x, unit_masses(x), plane_frame(dp));
    EXPECT_NEAR(heap.run_out, 150 * dp, 1e-12);
    EXPECT_NEAR(heap.run_out_99, 149 * dp, 1e-12);
    // Heavier particles in the last two columns (8 of 600 particles, each 10 times as heavy:
    // 80 of 672) move the 99 % point into them: 0.99 * 672 = 665.28, reached within the
    // 150th column (592 + 40 + 40 = 672 after it, 592 + 40 = 632 after the 149th).
    std::vector<double> m = unit_masses(x);
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (x[i].x() > 148 * dp) {
            m[i] = 10.0;
        }
    }
    EXPECT_NEAR(measure_heap(x, m, plane_frame(dp)).run_out_99, 150 * dp, 1e-12);
}

// A toe of 20 particles (2 % of the deposit's 1000) on the floor in front of a 100 x 10
// deposit: 1.4 dp from it the toe belongs to the heap's cluster, 1.6 dp from it it does not.
// The cluster's edge jumps by the toe's length (20.4 dp) between the two; the mass-based
// run-out, the far edge of the toe's tenth particle in both (0.99 * 1020 = 1009.8 particles),
// moves by the 0.2 dp the toe moved.
TEST(HeapMeasures, MassRunOutMovesWithTheToeWhereTheClusterEdgeJumps) {
    const double dp = 0.01;
    const auto linked = deposit_with_toe(dp, 100, 10, 20, 1.4 * dp);
    const auto parted = deposit_with_toe(dp, 100, 10, 20, 1.6 * dp);
    const HeapMeasures a = measure_heap(linked, unit_masses(linked), plane_frame(dp));
    const HeapMeasures b = measure_heap(parted, unit_masses(parted), plane_frame(dp));
    EXPECT_EQ(a.outside_count, 0);
    EXPECT_EQ(b.outside_count, 20);
    EXPECT_NEAR(a.run_out, 120.4 * dp, 1e-12);
    EXPECT_NEAR(b.run_out, 100 * dp, 1e-12);
    EXPECT_NEAR(a.run_out_99, 110.4 * dp, 1e-12);
    EXPECT_NEAR(b.run_out_99, 110.6 * dp, 1e-12);
}

// A lattice cone (30 deg, R = 30 dp, its axis on a cell corner) with its four axis columns
// (centres 0.71 dp from the axis) cut down to 10 layers: the height on the axis is their top,
// 10 dp exactly, while the highest particle of the heap stands beside the dip (the next ring's
// columns, 1.58 dp out, reach 16 dp).
TEST(HeapMeasures, AxisHeightIsTheTopOnTheAxisBesideADip) {
    const double dp = 0.01;
    auto x = lattice_cone(dp, 30 * dp, 30.0 * kDegree);
    const HeapMeasures whole = measure_heap(x, unit_masses(x), cone_frame(dp));
    EXPECT_NEAR(whole.axis_height, whole.final_height, 1e-12); // no dip: the apex is on the axis
    std::erase_if(x,
                  [dp](const Vec3& c) { return std::hypot(c.x(), c.y()) < dp && c.z() > 10 * dp; });
    const HeapMeasures dipped = measure_heap(x, unit_masses(x), cone_frame(dp));
    EXPECT_NEAR(dipped.axis_height, 10 * dp, 1e-12);
    EXPECT_NEAR(dipped.final_height, 16 * dp, 1e-12);
}

// The link distance decides: 1.4 and 1.6 spacings on either side of 1.5.
TEST(HeapMeasures, ClusterLinksCentresCloserThanTheLinkDistance) {
    const std::vector<Vec3> x{Vec3(0, 0, 0), Vec3(1.4, 0, 0), Vec3(2.8, 0, 0), Vec3(4.4, 0, 0)};
    const auto member = largest_cluster(x, 1.5);
    EXPECT_EQ(member, (std::vector<char>{1, 1, 1, 0}));
}

// Kinetic energy t on [0, 1], then e^-(t - 1)/tau: below 1e-4 of the peak (1) first at
// t = 1 + tau ln(1e4), found to within one sample interval.
TEST(RestDetector, FindsTheFirstTimeBelowTheFractionAfterThePeak) {
    const double tau = 0.05;
    const double interval = 1e-3;
    RestDetector rest(1e-4);
    for (int k = 0; k <= 2000; ++k) {
        const double t = k * interval;
        rest.add(t, t <= 1.0 ? t : std::exp(-(t - 1.0) / tau));
    }
    ASSERT_TRUE(rest.rest_time().has_value());
    EXPECT_NEAR(*rest.rest_time(), 1.0 + tau * std::log(1e4), interval);
    EXPECT_DOUBLE_EQ(rest.peak(), 1.0);
    EXPECT_NEAR(rest.peak_time(), 1.0, 1e-12);
}

// A second, higher peak after a first rest restarts the search; an energy that never falls
// below the fraction leaves the rest time empty ("not reached").
TEST(RestDetector, NewPeakRestartsAndNotReachedStaysEmpty) {
    RestDetector rest(1e-4);
    rest.add(0.1, 1.0);
    rest.add(0.2, 1e-5);
    ASSERT_TRUE(rest.rest_time().has_value());
    rest.add(0.3, 2.0);
    EXPECT_FALSE(rest.rest_time().has_value());
    rest.add(0.4, 1e-3);
    EXPECT_FALSE(rest.rest_time().has_value());
    RestDetector copy(1e-4);
    copy.set_state(rest.state());
    copy.add(0.5, 1e-4);
    ASSERT_TRUE(copy.rest_time().has_value());
    EXPECT_DOUBLE_EQ(*copy.rest_time(), 0.5);
}

} // namespace
} // namespace grainload::sph
