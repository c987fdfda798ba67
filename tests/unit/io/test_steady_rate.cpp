#include "io/steady_rate.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace grainload::io {
namespace {

// A discharge curve with a slow start (quadratic up to t = 1 s), a straight middle at 2 kg/s
// and a slow end: the fit over 20-80 % of the final mass sees only the straight middle and
// returns its slope to round-off, with the window it used.
TEST(SteadyRate, RecoversTheSlopeOfTheStraightMiddleOnly) {
    std::vector<double> t;
    std::vector<double> m;
    for (int k = 0; k <= 60; ++k) {
        const double time = 0.1 * k;
        t.push_back(time);
        // 0-1 s: M = t^2 (rate rising to 2); 1-5 s: M = 1 + 2 (t - 1) (to 9); then 1 kg/s to
        // 10 kg at 6 s.
        m.push_back(time < 1.0   ? time * time
                    : time < 5.0 ? 1.0 + 2.0 * (time - 1.0)
                                 : 9.0 + (time - 5.0));
    }
    const auto fit = steady_rate(t, m);
    ASSERT_TRUE(fit.has_value());
    // 20-80 % of 10 kg: M in [2, 8], t in [1.5, 4.5] on the straight part.
    constexpr double kRoundOff = 1e-12;
    EXPECT_NEAR(fit->rate, 2.0, kRoundOff);
    EXPECT_NEAR(fit->start, 1.5, kRoundOff);
    EXPECT_NEAR(fit->end, 4.5, kRoundOff);
    EXPECT_EQ(fit->samples, 31);
}

// Nothing discharged, or too few samples in the window for a line, gives no rate.
TEST(SteadyRate, NoRateWithoutEnoughSamples) {
    const std::vector<double> t{0.0, 1.0, 2.0, 3.0};
    EXPECT_FALSE(steady_rate(t, std::vector<double>{0.0, 0.0, 0.0, 0.0}).has_value());
    // Only M = 5 lies within [2, 8].
    EXPECT_FALSE(steady_rate(t, std::vector<double>{0.0, 0.0, 5.0, 10.0}).has_value());
    EXPECT_THROW(steady_rate(t, std::vector<double>{1.0}), std::invalid_argument);
}

} // namespace
} // namespace grainload::io
