#include "sph/sink.hpp"
#include "support/guide_table.hpp"

namespace grainload::sph {
namespace {

// The user guide's [[sph.sink]] and outlet tables list exactly the declared keys with their
// defaults.
TEST(SinkKeys, UserGuideStatesEveryKeyWithItsDefault) {
    testing::expect_guide_states(kSinkKeys, "docs/user-guide/sph.md", "## `[[sph.sink]]`");
    testing::expect_guide_states(kWallOutletKeys, "docs/user-guide/sph.md",
                                 "## Outlets and gates: `[[sph.wall]]` keys");
}

} // namespace
} // namespace grainload::sph
