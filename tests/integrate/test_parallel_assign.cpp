// parallel_assign (sim/core/parallel_assign.hpp) and the RK4(3) step that uses it on long
// vectors: the threaded evaluation must give the serial result bit for bit, so that a run's
// trajectory does not depend on how the state vectors were combined.
#include "sim/core/parallel_assign.hpp"
#include "sim/core/types.hpp"
#include "sim/integrate/rk43.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace crumple;

namespace {

VecX wavy(Eigen::Index n, double phase) {
  VecX v(n);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = std::sin(0.37 * i + phase) / (1.0 + 1e-3 * i);
  return v;
}

}  // namespace

TEST(ParallelAssign, EqualsSerialAssignmentBitForBit) {
  // Lengths below the threshold, at it, and above it with a ragged last chunk.
  for (Eigen::Index n : {Eigen::Index{1000}, kParallelAssignMin, Eigen::Index{100003}}) {
    const VecX a = wavy(n, 0.1), b = wavy(n, 2.3);
    const VecX serial = a + (1.0 / 3.0) * (b - 2.0 * a);
    VecX par;
    parallel_assign(par, a + (1.0 / 3.0) * (b - 2.0 * a));
    ASSERT_EQ(par.size(), n);
    EXPECT_TRUE((par.array() == serial.array()).all()) << "n = " << n;
  }
}

TEST(ParallelAssign, WritesIntoASegmentOnly) {
  const Eigen::Index n = 50001;
  VecX y = VecX::Constant(3 * n, -7.0);
  const VecX v = wavy(n, 0.5);
  auto mid = y.segment(n, n);
  parallel_assign(mid, 2.0 * v);
  EXPECT_TRUE((y.head(n).array() == -7.0).all());
  EXPECT_TRUE((y.segment(n, n).array() == (2.0 * v).array()).all());
  EXPECT_TRUE((y.tail(n).array() == -7.0).all());
}

TEST(ParallelAssign, Rk43StepOnALongVectorEqualsTheSerialFormulas) {
  // y' = -y .* w (decoupled decay, 60000 components): the step through parallel_assign against
  // the tableau's formulas evaluated by Eigen on one thread.
  const Eigen::Index n = 60000;
  const VecX w = wavy(n, 1.0).cwiseAbs(), y = wavy(n, 0.2);
  auto f = [&](double, const VecX& yy, VecX& dy) { dy = -(yy.array() * w.array()).matrix(); };
  const double h = 0.01;
  VecX k1, y4, y3, k5;
  f(0.0, y, k1);
  rk43_step(f, 0.0, y, h, k1, y4, y3, k5);

  VecX k2, k3, k4, e5;
  f(0.0, y + (0.5 * h) * k1, k2);
  f(0.0, y + (0.5 * h) * k2, k3);
  f(0.0, y + h * k3, k4);
  const VecX s4 = y + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  f(0.0, s4, e5);
  const VecX s3 = s4 + (h / 6.0) * (e5 - k4);
  EXPECT_TRUE((y4.array() == s4.array()).all());
  EXPECT_TRUE((y3.array() == s3.array()).all());
  EXPECT_TRUE((k5.array() == e5.array()).all());
}
