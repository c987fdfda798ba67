#include "particles/ordered_sum.hpp"

#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <omp.h>
#include <random>
#include <vector>

namespace grainload::particles {
namespace {

/// Terms of many magnitudes and both signs, so that the order of the sum shows in its bits.
std::vector<double> terms(Index n) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-20, 20);
    std::vector<double> t(static_cast<std::size_t>(n));
    for (double& x : t) {
        x = std::ldexp(mantissa(random), exponent(random));
    }
    return t;
}

bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(OrderedSum, GivesTheSameBitsOnAnyNumberOfThreads) {
    const Index n = 10 * kOrderedSumBlock + 17;
    const std::vector<double> t = terms(n);
    const int threads_before = omp_get_max_threads();
    omp_set_num_threads(1);
    const auto one = ordered_sums<2>(n, [&](Index i, std::array<double, 2>& s) {
        s[0] += t[i];
        s[1] += t[i] * t[i];
    });
    // A reduction clause's sum on several threads is ordered by the threads, and a serial sum
    // in the particles' order differs from the blocks' in the last bits: the test can tell.
    double serial = 0.0;
    for (const double x : t) {
        serial += x;
    }
    EXPECT_FALSE(same_bits(serial, one[0]));
    for (const int threads : {2, 3, 4}) {
        omp_set_num_threads(threads);
        const auto many = ordered_sums<2>(n, [&](Index i, std::array<double, 2>& s) {
            s[0] += t[i];
            s[1] += t[i] * t[i];
        });
        EXPECT_TRUE(same_bits(many[0], one[0])) << threads << " threads";
        EXPECT_TRUE(same_bits(many[1], one[1])) << threads << " threads";
    }
    omp_set_num_threads(threads_before);
    // Both are the sum to round-off: n terms below 2^20 in magnitude, error below n eps 2^20.
    EXPECT_NEAR(one[0], serial, static_cast<double>(n) * 2.3e-16 * std::ldexp(1.0, 20));
}

TEST(OrderedSum, IsThePlainSerialSumUpToOneBlock) {
    const Index n = kOrderedSumBlock;
    const std::vector<double> t = terms(n);
    double serial = 0.0;
    for (const double x : t) {
        serial += x;
    }
    EXPECT_TRUE(same_bits(ordered_sum(n, [&](Index i) { return t[i]; }), serial));
    EXPECT_EQ(ordered_sum(0, [&](Index i) { return t[i]; }), 0.0);
}

} // namespace
} // namespace grainload::particles
