#include "sph/lattice_fill.hpp"
#include "sph/pair_parts.hpp"
#include "sph/rates.hpp"

#include <gtest/gtest.h>
#include <omp.h>
#include <random>
#include <set>
#include <utility>

namespace grainload::sph {
namespace {

/// A 5 x 5 x 5 lattice (3D) or 9 x 9 (2D) at 0.1 m cut into two bodies at x = 0.25 m, with a
/// row of wall particles along x = 0: three kinds of pair (same body, two bodies, wall).
struct Scene {
    ParticleSet particles;
    SmoothingKernel kernel;
    particles::NeighbourList neighbours;
};

Scene make_scene(int dimension) {
    const double spacing = 0.1;
    ParticleSet particles;
    LatticeBody body;
    body.upper = Vec3::Constant((dimension == 3 ? 5 : 9) * spacing);
    body.spacing = spacing;
    body.density = 1000.0;
    fill_box_lattice(particles, body, dimension);
    for (Index i = 0; i < particles.size(); ++i) {
        particles.body_id[i] = particles.position[i].x() < 0.25 ? 0 : 1;
        if (particles.position[i].x() < 0.1) {
            particles.wall_id[i] = 0;
            particles.body_id[i] = 2;
        }
    }
    SmoothingKernel kernel(KernelType::cubic_spline, 1.3 * spacing, dimension);
    particles::NeighbourList neighbours(kernel.support_radius(), 0.02, dimension);
    std::vector<char> frozen(static_cast<std::size_t>(particles.size()));
    for (Index i = 0; i < particles.size(); ++i) {
        frozen[i] = particles.wall_id[i] >= 0 ? 1 : 0;
    }
    neighbours.update(particles.position, frozen, true);
    return {std::move(particles), kernel, std::move(neighbours)};
}

std::set<std::pair<Index, Index>> entries(const particles::NeighbourList& list, Index n) {
    std::set<std::pair<Index, Index>> all;
    for (Index i = 0; i < n; ++i) {
        for (const auto j : list.neighbours(i)) {
            all.emplace(i, j);
        }
    }
    return all;
}

TEST(PairParts, HalvedListKeepsEachSameBodyPairOnceAndOtherPairsInBothRows) {
    Scene s = make_scene(3);
    const Index n = s.particles.size();
    const auto full = entries(s.neighbours, n);
    const std::vector<int> key = continuum_keys(s.particles);
    s.neighbours.halve_pairs(key);
    const auto half = entries(s.neighbours, n);
    std::size_t same = 0;
    for (const auto& [i, j] : full) {
        const bool same_body = s.particles.wall_id[i] < 0 && s.particles.wall_id[j] < 0 &&
                               s.particles.body_id[i] == s.particles.body_id[j];
        same += same_body ? 1 : 0;
        // Same body: in the lower index's row only; otherwise as built.
        EXPECT_EQ(half.count({i, j}), same_body && j < i ? 0u : 1u) << i << " " << j;
    }
    EXPECT_GT(same, 0u);
    EXPECT_EQ(half.size(), full.size() - same / 2);
    EXPECT_EQ(static_cast<std::size_t>(s.neighbours.pair_entries()), half.size());
}

TEST(PairParts, SplitRowsGivesPartsOfEvenEntriesWhoseWindowsHoldEveryPairTheyAdd) {
    Scene s = make_scene(3);
    const Index n = s.particles.size();
    const std::vector<int> key = continuum_keys(s.particles);
    // The list as built (both rows of each pair): no reach known, every window is the rest of
    // the particles.
    const PairParts whole = split_rows(s.neighbours, n, n, 3);
    for (int r = 0; r < whole.count(); ++r) {
        EXPECT_EQ(whole.reach[static_cast<std::size_t>(r)], n);
    }
    s.neighbours.halve_pairs(key);
    ASSERT_TRUE(s.neighbours.halved());
    auto row_cost = [&](Index i) { return static_cast<Index>(s.neighbours.neighbours(i).size()); };
    Index total = 0;
    Index costliest = 0;
    for (Index i = 0; i < n; ++i) {
        total += row_cost(i);
        costliest = std::max(costliest, row_cost(i));
    }
    for (const int count : {1, 2, 3, 7, 8}) {
        const PairParts parts = split_rows(s.neighbours, n, n, count);
        ASSERT_EQ(parts.count(), count);
        EXPECT_EQ(parts.bounds.front(), 0);
        EXPECT_EQ(parts.bounds.back(), n);
        const double even = static_cast<double>(total) / count;
        for (int r = 0; r < count; ++r) {
            const auto part = static_cast<std::size_t>(r);
            ASSERT_LE(parts.bounds[part], parts.bounds[part + 1]);
            Index cost = 0;
            for (Index i = parts.bounds[part]; i < parts.bounds[part + 1]; ++i) {
                cost += row_cost(i);
                // The window holds the row itself and every particle its pairs add to.
                EXPECT_LT(i, parts.reach[part]);
                for (const auto j : s.neighbours.neighbours(i)) {
                    if (key[i] == key[j]) {
                        EXPECT_GE(j, parts.origin(r) == 0 ? 0 : parts.bounds[part]);
                        EXPECT_LT(j, parts.reach[part]) << count << " parts, row " << i;
                    }
                }
            }
            // Rows are whole: a part misses the even share by less than a row at each end.
            EXPECT_NEAR(static_cast<double>(cost), even, 2.0 * static_cast<double>(costliest))
                << count << " parts, part " << r;
            // The window ends where the last pair of the rows up to the part's end reaches (a
            // prefix maximum over the rows, computed here by brute force), not at the last
            // particle: later parts zero and sum only that.
            Index reach = parts.bounds[part + 1];
            for (Index i = 0; i < parts.bounds[part + 1]; ++i) {
                for (const auto j : s.neighbours.neighbours(i)) {
                    reach = key[i] == key[j] ? std::max(reach, static_cast<Index>(j) + 1) : reach;
                }
            }
            EXPECT_EQ(parts.reach[part], reach) << count << " parts, part " << r;
        }
    }
}

/// The rates by the formulas of rates.hpp summed over every ordered pair (i, j), both ways,
/// with no list: L_i = sum_j m_j / rho_i (v_j - v_i) grad_i W_ij^T, a_i = g + sum_j m_j
/// (sigma_i / rho_i^2 + sigma_j / rho_j^2 - Pi_ij I) grad_i W_ij, de_i/dt = 1/2 sum_j m_j Pi_ij
/// v_ij . grad_i W_ij, over pairs of one body (no contact here).
struct Direct {
    std::vector<Mat3> l;
    std::vector<Vec3> a;
    std::vector<double> heating;
};

Direct direct_rates(const ParticleSet& p, const SmoothingKernel& kernel, const SphOptions& o) {
    const Index n = p.size();
    Direct d{std::vector<Mat3>(n, Mat3::Zero()), std::vector<Vec3>(n, Vec3::Zero()),
             std::vector<double>(n, 0.0)};
    const double h = kernel.smoothing_length();
    for (Index i = 0; i < n; ++i) {
        if (p.wall_id[i] >= 0) {
            continue;
        }
        d.a[i] = o.gravity;
        for (Index j = 0; j < n; ++j) {
            const Vec3 x_ij = p.position[i] - p.position[j];
            const double r = x_ij.norm();
            if (j == i || p.wall_id[j] >= 0 || p.body_id[j] != p.body_id[i] ||
                r >= kernel.support_radius()) {
                continue;
            }
            const Vec3 g = kernel.gradient(x_ij, r);
            const Vec3 v_ij = p.velocity[i] - p.velocity[j];
            d.l[i] += p.mass[j] / p.density[i] * (-v_ij) * g.transpose();
            const double mu = h * v_ij.dot(x_ij) / (r * r + 0.01 * h * h);
            const double pi = v_ij.dot(x_ij) < 0.0
                                  ? (-o.viscosity.alpha * 100.0 * mu + o.viscosity.beta * mu * mu) /
                                        (0.5 * (p.density[i] + p.density[j]))
                                  : 0.0;
            const Mat3 t = stress_tensor(p.stress[i]) / (p.density[i] * p.density[i]) +
                           stress_tensor(p.stress[j]) / (p.density[j] * p.density[j]) -
                           pi * Mat3::Identity();
            d.a[i] += p.mass[j] * t * g;
            d.heating[i] += 0.5 * p.mass[j] * pi * v_ij.dot(g);
        }
    }
    return d;
}

TEST(PairParts, PassesTakingEachPairOnceMatchTheDirectSumsOnAnyNumberOfThreads) {
    const int threads_before = omp_get_max_threads();
    for (const int dimension : {2, 3}) {
        Scene s = make_scene(dimension);
        ParticleSet& p = s.particles;
        std::mt19937 generator(7u);
        std::uniform_real_distribution<double> value(-1.0, 1.0);
        for (Index i = 0; i < p.size(); ++i) {
            for (int c = 0; c < 6; ++c) {
                p.stress[i][c] = 1e4 * value(generator);
            }
            p.velocity[i] = Vec3(value(generator), value(generator), value(generator));
            if (dimension == 2) {
                p.stress[i][4] = p.stress[i][5] = 0.0;
                p.velocity[i].z() = 0.0;
            }
        }
        SphOptions options;
        options.dimension = dimension;
        options.particle_spacing = 0.1;
        options.viscosity = {1.0, 2.0};
        options.gravity = Vec3(0.0, -9.81, 0.0);
        options.contact.stiffness = 0.0; // pairs of two bodies or a wall exchange nothing
        const Direct direct = direct_rates(p, s.kernel, options);
        // Round-off of sums of about 50 terms of either sign, in another order: relative to
        // the largest value of each rate.
        double l_scale = 0.0;
        double a_scale = 0.0;
        double heating_scale = 0.0;
        for (Index i = 0; i < p.size(); ++i) {
            l_scale = std::max(l_scale, direct.l[i].norm());
            a_scale = std::max(a_scale, direct.a[i].norm());
            heating_scale = std::max(heating_scale, std::abs(direct.heating[i]));
        }
        constexpr double kRoundOff = 1e-13;
        ASSERT_GT(heating_scale, 0.0);
        // The solver's list (each same-body pair once) and the list as built (both rows; the
        // passes skip the second), on 1 to 3 threads.
        for (const bool halve : {false, true}) {
            if (halve) {
                s.neighbours.halve_pairs(continuum_keys(p));
            }
            for (const int threads : {1, 2, 3}) {
                omp_set_num_threads(threads);
                PairScratch scratch;
                ForceInputs inputs;
                inputs.sound_speed.assign(static_cast<std::size_t>(p.size()), 100.0);
                std::vector<Mat3> gradient;
                compute_velocity_gradient(p, s.neighbours, s.kernel, false, gradient,
                                          inputs.gradient_correction, nullptr, &scratch);
                prepare_force_inputs(p, options.artificial_stress, inputs);
                std::vector<double> heating;
                compute_accelerations(p, s.neighbours, s.kernel, options, inputs, heating,
                                      &scratch);
                for (Index i = 0; i < p.size(); ++i) {
                    const std::string where =
                        std::to_string(dimension) + "D, halved " + std::to_string(halve) + ", " +
                        std::to_string(threads) + " threads, particle " + std::to_string(i);
                    EXPECT_LT((gradient[i] - direct.l[i]).norm(), kRoundOff * 50.0 * l_scale)
                        << where;
                    EXPECT_LT((p.acceleration[i] - direct.a[i]).norm(), kRoundOff * 50.0 * a_scale)
                        << where;
                    EXPECT_NEAR(heating[i], direct.heating[i], kRoundOff * 50.0 * heating_scale)
                        << where;
                }
            }
        }
    }
    omp_set_num_threads(threads_before);
}

} // namespace
} // namespace grainload::sph
