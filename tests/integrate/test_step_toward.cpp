// step_toward (sim/integrate/step_toward.hpp): the steps onto an interval's end are equal, land
// on it exactly, and are never longer than the controller's step nor much shorter.
#include "sim/integrate/step_toward.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace crumple;

TEST(StepToward, FarFromTheEndTakesTheControllersStep) {
  EXPECT_EQ(step_toward(10.0, 1.0), 1.0);
  EXPECT_EQ(step_toward(4.5, 1.0), 1.0);  // five steps: beyond the default four
}

TEST(StepToward, TheRestInOneStepWhenItFits) {
  EXPECT_EQ(step_toward(0.3, 1.0), 0.3);
  EXPECT_EQ(step_toward(1.0, 1.0), 1.0);
}

TEST(StepToward, ExactMultiplesKeepTheStep) {
  EXPECT_DOUBLE_EQ(step_toward(3.0, 1.0), 1.0);
  // Rounding of the quotient does not add a step.
  EXPECT_DOUBLE_EQ(step_toward(0.3, 0.1), 0.1);
}

TEST(StepToward, ShortRestIsSplitEvenly) {
  EXPECT_DOUBLE_EQ(step_toward(2.1, 1.0), 0.7);
  EXPECT_DOUBLE_EQ(step_toward(1.05, 1.0), 0.525);
  EXPECT_DOUBLE_EQ(step_toward(3.6, 1.0), 0.9);
}

// With a fixed controller step, repeated steps reach the end exactly in the fewest steps, none
// shorter than (m - 1) / m of it, m = min(steps, max_equal): no sliver at any interval length.
TEST(StepToward, RepeatedStepsLandWithoutASliver) {
  const double h = 0.37;
  for (int k = 1; k <= 200; ++k) {
    const double length = 0.013 * k;
    double t = 0, shortest = h;
    int steps = 0;
    while (length - t > 1e-13) {
      const double dt = step_toward(length - t, h);
      ASSERT_LE(dt, h * (1 + 1e-12));
      t += dt;
      ++steps;
      if (length - t > 1e-13) shortest = std::min(shortest, dt);
    }
    EXPECT_NEAR(t, length, 1e-12);
    EXPECT_EQ(steps, static_cast<int>(std::ceil(length / h * (1 - 1e-12))));
    const int m = std::min(steps, 4);
    EXPECT_GE(shortest, (m - 1.0) / m * h * (1 - 1e-12)) << "length " << length;
  }
}

// Growing plans: from a first step below the proposal (the growth limit over a short last
// step), the steps onto the end grow by at most `growth`, land exactly, and take no more steps
// than the fastest admissible sequence would.
TEST(StepToward, PlannedStepsGrowWithinTheRatioAndLand) {
  const double proposal = 0.05, growth = 1.22;
  for (int k = 1; k <= 300; ++k) {
    const double length = 0.0011 * k;
    double t = 0, prev = 0.0325;  // the step before: the first may be growth * prev at most
    int steps = 0;
    while (length - t > 1e-13) {
      const double first = std::min(proposal, growth * prev);
      const double dt = step_toward(length - t, first, proposal, growth);
      ASSERT_LE(dt, first * (1 + 1e-12));
      ASSERT_GT(dt, 0.0);
      t += dt;
      prev = dt;
      ++steps;
    }
    EXPECT_NEAR(t, length, 1e-12);
    // The fewest steps any admissible sequence needs.
    double fastest = 0, s = 0.0325;
    int needed = 0;
    while (fastest < length * (1 - 1e-12)) {
      s = std::min(proposal, growth * s);
      fastest += s;
      ++needed;
    }
    EXPECT_LE(steps, needed + 1) << "length " << length;
  }
  // The case equal steps cannot leave: a chunk of 2.6 proposals entered at 0.65 of the proposal
  // is done in 3 steps, not 4 (4 / 3 is a larger ratio than 1.22).
  const double first = growth * 0.0325;
  const double dt = step_toward(0.13, first, proposal, growth);
  EXPECT_LT(dt, first);
  EXPECT_GT(dt, 0.13 / 3 * 0.8);
}
