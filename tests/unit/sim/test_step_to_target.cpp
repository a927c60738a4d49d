// How a run reaches its output times: equal steps no longer than the stable one (sim/step_to_target.hpp).
#include <gtest/gtest.h>

#include <algorithm>

#include "grit/sim/step_to_target.hpp"

namespace {

using grit::sim::step_toward;

TEST(StepToTarget, ALastStepWithinReachLandsOnTheTarget) {
    EXPECT_EQ(step_toward(1.0e-6, 1.2e-6, 3.0e-7), 1.2e-6 - 1.0e-6);
    EXPECT_EQ(step_toward(0.0, 2.0e-9, 2.0e-9), 2.0e-9);
}

// 1 us in steps of at most 3 ns: 334 steps of 2.994 ns, not 333 of 3 ns and a sliver of 1 ns. Every
// step within 1e-9 of the first, none above the stable step, and the last lands on the target.
TEST(StepToTarget, TheStepsToATargetAreEqual) {
    const double target = 1.0e-6, dt = 3.0e-9;
    double time = 0.0, smallest = dt, largest = 0.0;
    int steps = 0;
    while (time < target) {
        const double step = step_toward(time, target, dt);
        ASSERT_GT(step, 0.0);
        smallest = std::min(smallest, step);
        largest = std::max(largest, step);
        time += step;
        ++steps;
    }
    EXPECT_EQ(steps, 334);
    EXPECT_LE(largest, dt);
    EXPECT_NEAR(smallest / largest, 1.0, 1e-9);
    EXPECT_DOUBLE_EQ(time, target);
}

// A stable step that changes on the way (as the CFL step does) changes the split with it, by 1/n.
TEST(StepToTarget, AShorterStableStepSplitsTheRestAgain) {
    const double first = step_toward(0.0, 1.0e-6, 3.0e-9);
    const double second = step_toward(first, 1.0e-6, 2.5e-9);
    EXPECT_LE(second, 2.5e-9);
    EXPECT_GT(second, 2.5e-9 * (1.0 - 1.0 / 399.0));
}

}  // namespace
