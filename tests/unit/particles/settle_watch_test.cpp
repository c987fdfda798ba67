#include "particles/settle_watch.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace grainload::particles {
namespace {

// Peak 10 J at t = 1; fraction 0.1: 0.5 J at t = 2 is before `after` (2.5 s) and does not
// settle, 0.9 J at t = 3 does (below 1 J), once; the state restores peak and time.
TEST(SettleWatch, SettlesOnceBelowTheFractionOfThePeakAfterTheStart) {
    SettleWatch watch(0.1, 2.5);
    EXPECT_FALSE(watch.record(1.0, 10.0));
    EXPECT_FALSE(watch.record(2.0, 0.5));
    EXPECT_FALSE(watch.record(2.7, 1.5));
    EXPECT_TRUE(watch.record(3.0, 0.9));
    EXPECT_FALSE(watch.record(3.5, 0.1)) << "settles once";
    EXPECT_EQ(watch.settle_time(), 3.0);
    SettleWatch copy(0.1, 2.5);
    copy.set_state(watch.state());
    EXPECT_TRUE(copy.settled());
    EXPECT_EQ(copy.peak(), 10.0);
    EXPECT_THROW(copy.set_state({1.0}), std::runtime_error);
}

} // namespace
} // namespace grainload::particles
