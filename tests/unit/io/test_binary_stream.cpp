// Counts kept as doubles in a module's checkpoint state (io/binary_stream.hpp, state_count): a
// corrupt checkpoint may hold any double there. fuzz_checkpoint found the coupling monitor's
// count of growing windows cast from 5.39e67 to int (undefined behaviour; the input is
// tests/fuzz/regressions/checkpoint/coupling_growing_windows_5e67); a source's cursor and the
// sinks' row count were cast the same way, and the cursor then indexed the sites unchecked.

#include "io/binary_stream.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace grainload::io {
namespace {

TEST(BinaryStream, StateCountsAreWholeNumbersInRange) {
    // The range's ends are exact doubles, so both are accepted as they are.
    EXPECT_EQ(state_count(0.0, 7.0, "cursor"), 0u);
    EXPECT_EQ(state_count(7.0, 7.0, "cursor"), 7u);
    EXPECT_EQ(state_count(9007199254740992.0, 9007199254740992.0, "steps"), 9007199254740992u);
    for (const double bad : {-1.0, 8.0, 2.5, 5.39199e67, std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity()}) {
        EXPECT_THROW(state_count(bad, 7.0, "cursor"), std::runtime_error) << bad;
    }
}

} // namespace
} // namespace grainload::io
