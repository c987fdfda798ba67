#include "io/step_collapse.hpp"

#include <gtest/gtest.h>

namespace {

using grainload::io::StepCollapseWatch;

// The watch compares each step with the largest before it: a fall to just above a thousandth
// passes, just below is a collapse, and a step that grows again raises the reference.
TEST(StepCollapseWatch, AThousandfoldFallFromTheLargestStepIsACollapse) {
    StepCollapseWatch watch;
    EXPECT_FALSE(watch.record(1e-3, 0.0));
    EXPECT_FALSE(watch.record(5e-4, 0.1));    // a step halved by a faster flow
    EXPECT_FALSE(watch.record(1.01e-6, 0.2)); // above 1e-3 of the largest, 1e-3 s
    const auto collapse = watch.record(0.99e-6, 0.3);
    ASSERT_TRUE(collapse);
    EXPECT_NE(collapse->find("fell to 9.9e-07 s at t = 0.3 s"), std::string::npos) << *collapse;
    EXPECT_NE(collapse->find("largest so far (0.001 s)"), std::string::npos) << *collapse;
    StepCollapseWatch growing;
    EXPECT_FALSE(growing.record(1e-6, 0.0));
    EXPECT_FALSE(growing.record(1e-2, 0.1));
    EXPECT_TRUE(growing.record(5e-6, 0.2));            // below 1e-3 of 1e-2 s
    EXPECT_TRUE(StepCollapseWatch().record(0.0, 0.0)); // a zero step is never a step
}

} // namespace
