// The non-local fluidity's field equation on particles: the discrete Laplacian of a quadratic,
// and the screened Poisson problem of a step source against its closed-form solution, on a
// lattice periodic across the profile (select_images), at two spacings.

#include "particles/neighbour_list.hpp"
#include "sph/fluidity_field.hpp"
#include "sph/fluidity_update.hpp"
#include "sph/kernels.hpp"
#include "sph/symmetry.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <vector>

namespace grainload::sph {
namespace {

// A lattice of spacing dx, `columns` wide from x0 and `rows` high from y = 0, periodic along
// `periodic_axis` (0: x, 1: y) over its extent, its images attached and the field connected and
// weighed (h = 1.3 dx, the solver's default).
struct Lattice {
    Index count = 0;
    std::vector<Vec3> positions; // particles, then images
    FluidityField field;

    Lattice(double dx, double x0, int columns, int rows, int periodic_axis) {
        for (int r = 0; r < rows; ++r) {
            for (int c = 0; c < columns; ++c) {
                positions.emplace_back(x0 + (c + 0.5) * dx, (r + 0.5) * dx, 0.0);
            }
        }
        count = static_cast<Index>(positions.size());
        const SmoothingKernel kernel(KernelType::cubic_spline, 1.3 * dx, 2);
        const std::array<PeriodicAxis, 1> periodic{periodic_axis == 0
                                                       ? PeriodicAxis{0, x0, x0 + columns * dx}
                                                       : PeriodicAxis{1, 0.0, rows * dx}};
        const std::vector<char> none(positions.size(), 0);
        const std::vector<MirrorMask> allowed(positions.size(), 0);
        const auto images =
            select_images({}, periodic, positions, none, allowed, kernel.support_radius());
        const ImageFrame frame = image_frame({}, periodic);
        std::vector<Index> sources;
        for (const GhostImage& image : images) {
            positions.push_back(image_position(positions[image.source], image, frame));
            sources.push_back(image.source);
        }
        particles::NeighbourList list(kernel.support_radius(), 0.0, 2);
        list.update(positions, {}, true, count);
        const std::vector<char> carries(static_cast<std::size_t>(count), 1);
        const std::vector<int> body(static_cast<std::size_t>(count), 0);
        field.connect(list, count, sources, carries, body);
        const std::vector<double> volume(static_cast<std::size_t>(count), dx * dx);
        field.weigh(positions, volume, carries, kernel);
    }
};

// Brookshaw's form on a regular lattice: sum_j a_ij (x_j - x_i)^2 is the lattice sum of the
// kernel's second moment (less the eta^2 regulariser's share), which the integral gives as 2
// exactly. At h = 1.3 dx the lattice sum differs from it by a fixed fraction that refining the
// lattice at a fixed h / dx does not remove: measured 1.6e-4 of 2 with the cubic spline, allowed
// 1e-3.
TEST(FluidityField, TheLaplacianOfAQuadraticIsTwo) {
    constexpr double kSecondMomentTolerance = 1e-3;
    const double dx = 1e-3;
    Lattice lattice(dx, -20 * dx, 40, 16, 1);
    std::vector<double> g(static_cast<std::size_t>(lattice.count));
    for (Index i = 0; i < lattice.count; ++i) {
        g[i] = lattice.positions[i].x() * lattice.positions[i].x();
    }
    double worst = 0.0;
    for (Index i = 0; i < lattice.count; ++i) {
        if (std::abs(lattice.positions[i].x()) < 15 * dx) { // a full support inside the lattice
            worst = std::max(worst, std::abs(lattice.field.laplacian(g, i) / 2.0 - 1.0));
        }
    }
    std::printf("worst relative error of the Laplacian of x^2: %.4g\n", worst);
    EXPECT_LT(worst, kSecondMomentTolerance);
}

// g - xi^2 g'' = g_loc with g_loc = G0 for x < 0 and 0 beyond, constant xi, on the whole line:
// g = G0 (1 - exp(x/xi)/2) for x < 0 and G0 exp(-x/xi)/2 for x > 0 (continuous with its
// slope at the step). The lattice ends 8 xi from the step, where the zero-flux condition of the
// particle sums differs from the infinite line's slope by exp(-8) = 3e-4 of G0.
double step_profile(double x, double xi) {
    return x < 0.0 ? 1.0 - 0.5 * std::exp(x / xi) : 0.5 * std::exp(-x / xi);
}

double worst_profile_error(double xi, double dx) {
    Lattice lattice(dx, -8.0 * xi, static_cast<int>(std::lround(16.0 * xi / dx)), 8, 1);
    const auto n = static_cast<std::size_t>(lattice.count);
    std::vector<double> local(n);
    std::vector<double> screening(n, 1.0 / (xi * xi));
    std::vector<double> g(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        local[i] = lattice.positions[i].x() < 0.0 ? 1.0 : 0.0;
    }
    const FluiditySolve done = lattice.field.solve(local, screening, g, 20000, 1e-12);
    EXPECT_LT(done.residual, 1e-12) << "not converged in " << done.iterations << " iterations";
    double worst = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        worst = std::max(worst, std::abs(g[i] - step_profile(lattice.positions[i].x(), xi)));
    }
    return worst;
}

// Measured: 4.9e-3 G0 at dx = xi/4 and 1.3e-3 G0 at dx = xi/8, a fall of 3.6 where second order
// gives 4 (the source's step leaves g'' discontinuous). Allowed: 2e-3 G0 at xi/8 (the end
// condition's 3e-4 and the second moment's lattice error below it), and a fall of more than 3,
// which a first-order form (a fall of 2) would not pass.
TEST(FluidityField, AStepSourceGivesTheExponentialProfile) {
    constexpr double kProfileTolerance = 2e-3;
    constexpr double kSecondOrderFall = 3.0;
    const double xi = 4e-3;
    const double coarse = worst_profile_error(xi, xi / 4.0);
    const double fine = worst_profile_error(xi, xi / 8.0);
    std::printf("worst error of g / G0: %.4g at dx = xi/4, %.4g at dx = xi/8\n", coarse, fine);
    EXPECT_LT(fine, kProfileTolerance);
    EXPECT_GT(coarse / fine, kSecondOrderFall);
}

// The field is solved at the first step into each interval of the clock: over 1 s of steps of
// 3e-5 s (not a divisor of the interval) an interval of 1e-4 s gives 10 000 solves, the last
// interval's included; 0 solves every step.
TEST(FluidityField, TheSolveIsDueOnceInEachIntervalOfTheClock) {
    const double dt = 3e-5;
    int due = 0, every = 0;
    int steps = 0;
    for (double t = 0.0; t < 1.0 - 0.5 * dt; t += dt) {
        due += FluidityUpdate::due(t, dt, 1e-4) ? 1 : 0;
        every += FluidityUpdate::due(t, dt, 0.0) ? 1 : 0;
        ++steps;
    }
    EXPECT_NEAR(due, 10000, 1); // the clock's round-off may move the last crossing by a step
    EXPECT_EQ(every, steps);
}

// The layer of an inclined-plane flow: g_loc grows as sqrt(H - y) with the depth (the pressure's
// square root), xi is constant (mu = tan theta everywhere), and the particle sums leave both
// the base and the free surface without neighbours beyond them: zero flux at both. Reference:
// the same equation in one dimension by second-order finite differences on 800 cells, zero flux
// by reflection (Eigen's LU; 1600 cells move it by under 1e-4). Each row's mean over
// a period along the layer against it, xi = 3.44 mm (A = 0.5, d = 2 mm, tan 25 deg) and H =
// 20 mm as in docs/validation/inclined_plane.md. Measured: 1.4 % at 10 particles across H (the
// worst row two below the surface), 0.6 % at 20; allowed 2 % and a fall with the spacing.
double worst_layer_error(int rows) {
    const double depth = 0.02, xi = 3.441e-3, dx = depth / rows;
    const int columns = 10;
    Lattice lattice(dx, 0.0, columns, rows, 0);
    const auto n = static_cast<std::size_t>(lattice.count);
    std::vector<double> local(n), screening(n, 1.0 / (xi * xi)), g(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        local[i] = std::sqrt(depth - lattice.positions[i].y());
    }
    lattice.field.solve(local, screening, g, 20000, 1e-12);

    const int cells = 800;
    const double h = depth / cells, k = xi * xi / (h * h);
    Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(cells + 1, cells + 1);
    Eigen::VectorXd source(cells + 1);
    for (int i = 0; i <= cells; ++i) {
        matrix(i, i) = 1.0 + 2.0 * k;
        matrix(i, i == 0 ? 1 : i - 1) -= k; // g' = 0 at both ends by reflection
        matrix(i, i == cells ? cells - 1 : i + 1) -= k;
        source[i] = std::sqrt(depth - i * h);
    }
    const Eigen::VectorXd reference = matrix.partialPivLu().solve(source);
    double worst = 0.0;
    for (int r = 0; r < rows; ++r) {
        double mean = 0.0;
        for (int c = 0; c < columns; ++c) {
            mean += g[static_cast<std::size_t>(r * columns + c)] / columns;
        }
        const double at = reference[std::lround((r + 0.5) * dx / h)];
        worst = std::max(worst, std::abs(mean / at - 1.0));
    }
    return worst;
}

TEST(FluidityField, ALayerWithAFreeSurfaceHasTheOneDimensionalProfile) {
    constexpr double kLayerTolerance = 0.02;
    const double coarse = worst_layer_error(10);
    const double fine = worst_layer_error(20);
    std::printf("worst relative error of the rows' g: %.4g at 10 rows, %.4g at 20\n", coarse, fine);
    EXPECT_LT(coarse, kLayerTolerance);
    EXPECT_LT(fine, coarse);
}
} // namespace
} // namespace grainload::sph
