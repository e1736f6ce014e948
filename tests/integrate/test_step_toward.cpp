// step_toward (sim/integrate/step_toward.hpp): the steps onto an interval's end land on it
// exactly, never exceed the largest admissible step nor the growth ratio, are planned equal when
// there is no growth to plan (none a sliver), and rounding of the rest never adds a step.
#include "sim/integrate/step_toward.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace crumple;

namespace {

// The rounding tolerance for intervals ending near t = 1 (landing_tolerance(1) is 3.6e-15;
// these cases do their own arithmetic at about that level).
constexpr double kTol = 1e-14;

// Equal steps: the controller's step h and nothing to grow.
double equal_step(double remaining, double h) { return step_toward(remaining, h, h, 1.0, kTol); }

}  // namespace

TEST(StepToward, FarFromTheEndTakesTheFirstStep) {
  EXPECT_EQ(equal_step(10.0, 1.0), 1.0);
  EXPECT_EQ(equal_step(4.5, 1.0), 1.0);  // five steps: beyond the default four
  EXPECT_EQ(step_toward(10.0, 0.5, 1.0, 1.22, kTol), 0.5);
}

TEST(StepToward, TheRestInOneStepWhenItFits) {
  EXPECT_EQ(equal_step(0.3, 1.0), 0.3);
  EXPECT_EQ(equal_step(1.0, 1.0), 1.0);
  EXPECT_EQ(equal_step(1.0 + 0.5 * kTol, 1.0), 1.0 + 0.5 * kTol);  // within rounding
}

TEST(StepToward, ExactMultiplesKeepTheStep) {
  EXPECT_DOUBLE_EQ(equal_step(3.0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(equal_step(0.3, 0.1), 0.1);  // 0.3 / 0.1 rounds above 3
}

TEST(StepToward, ShortRestIsSplitEvenly) {
  EXPECT_DOUBLE_EQ(equal_step(2.1, 1.0), 0.7);
  EXPECT_DOUBLE_EQ(equal_step(1.05, 1.0), 0.525);
  EXPECT_DOUBLE_EQ(equal_step(3.6, 1.0), 0.9);
}

// With a fixed controller step, repeated steps reach the end exactly in the fewest steps, none
// shorter than (m - 1) / m of it, m = min(steps, max_steps): no sliver at any interval length.
TEST(StepToward, RepeatedEqualStepsLandWithoutASliver) {
  auto walk = [](double length, double h, double& shortest) {
    double t = 0;
    int steps = 0;
    shortest = h;
    while (length - t > kTol) {
      const double dt = equal_step(length - t, h);
      EXPECT_LE(dt, h + kTol);
      t += dt;
      ++steps;
      if (length - t > kTol) shortest = std::min(shortest, dt);
    }
    EXPECT_NEAR(t, length, 1e-12);
    return steps;
  };
  const double h = 0.37;
  for (int k = 1; k <= 200; ++k) {
    const double length = 0.013 * k;
    double shortest;
    const int steps = walk(length, h, shortest);
    EXPECT_EQ(steps, static_cast<int>(std::ceil(length / h * (1 - 1e-12))));
    const int m = std::min(steps, 4);
    EXPECT_GE(shortest, (m - 1.0) / m * h * (1 - 1e-12)) << "length " << length;
  }
  // Six steps exactly, up to rounding: not seven (a tolerance relative to the rest of the
  // interval took 1, 1, 1, 0.75, 0.75, 0.75, 0.75 steps here).
  double shortest;
  EXPECT_EQ(walk(0.0080221221338633748, 0.0013370203556429105, shortest), 6);
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
    while (length - t > kTol) {
      const double first = std::min(proposal, growth * prev);
      const double dt = step_toward(length - t, first, proposal, growth, kTol);
      ASSERT_LE(dt, first + kTol);
      ASSERT_GT(dt, 0.0);
      t += dt;
      prev = dt;
      ++steps;
    }
    EXPECT_NEAR(t, length, 1e-12);
    // The fewest steps any admissible sequence needs.
    double fastest = 0, s = 0.0325;
    int needed = 0;
    while (fastest < length - kTol) {
      s = std::min(proposal, growth * s);
      fastest += s;
      ++needed;
    }
    EXPECT_EQ(steps, needed) << "length " << length;
  }
  // The case equal steps cannot leave: a chunk of 2.6 proposals entered at 0.65 of the proposal
  // is done in 3 steps, not 4 (4 / 3 is a larger ratio than 1.22).
  const double first = growth * 0.0325;
  const double dt = step_toward(0.13, first, proposal, growth, kTol);
  EXPECT_LT(dt, first);
  EXPECT_GT(dt, 0.13 / 3 * 0.8);
}

// At t ~ 50 the rest t_end - t carries an absolute rounding error of ~1e-14: an exact two-step
// fit (first, then growth * first) must stay two steps with the integrator's tolerance there.
TEST(StepToward, ExactFitAtLargeTimeIsNotOneStepMore) {
  const double first = 0.0029637337063726931, growth = 1.22;
  // first + growth * first, 1.8e-14 short (2.8e-12 of the rest: more than a tolerance relative
  // to the rest allowed, less than the absolute one at t = 50).
  const double rest = 0.0065794888281658359;
  const double dt = step_toward(rest, first, 100.0, growth, landing_tolerance(50.0));
  EXPECT_NEAR(dt, first, 1e-11);
}

// A retry after a rejection passes no tolerance: the cut step is taken, not a rest within
// rounding of it (with a tolerance of several steps, retries repeated one rejected step).
TEST(StepToward, NoToleranceTakesTheCutStep) {
  EXPECT_EQ(step_toward(1.2e-11, 3e-12, 3e-12, 2.0, 0.0), 3e-12);
  EXPECT_EQ(step_toward(3e-12, 3e-12, 3e-12, 2.0, 0.0), 3e-12);
}
