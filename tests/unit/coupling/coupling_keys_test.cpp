#include "coupling/coupling_case_reader.hpp"
#include "support/guide_table.hpp"

#include <gtest/gtest.h>

namespace grainload::coupling {
namespace {

// The user guide's [coupling] tables list exactly the declared keys with their defaults.
TEST(CouplingKeys, UserGuideStatesEveryKeyWithItsDefault) {
    const std::string page = "docs/user-guide/coupling.md";
    testing::expect_guide_states(kCouplingKeys, page, "## `[coupling]`");
    testing::expect_guide_states(kInterfaceKeys, page, "## `[[coupling.interface]]`");
}

} // namespace
} // namespace grainload::coupling
