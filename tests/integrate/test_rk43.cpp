// The explicit RK4(3) pair (sim/integrate/rk43.hpp): order conditions of both weight sets and
// measured global convergence orders of the fourth- and embedded third-order solutions.
#include "sim/integrate/rk43.hpp"

#include <Eigen/Core>
#include <gtest/gtest.h>

#include <cmath>

using namespace crumple;
using T = Rk43Tableau;

namespace {

double sum_b(const std::array<double, 5>& b, auto&& term) {
  double s = 0;
  for (int i = 0; i < 5; ++i) s += b[i] * term(i);
  return s;
}
double Ac(int i, int power) {  // (A c^power)_i
  double s = 0;
  for (int j = 0; j < 5; ++j) s += T::a[i][j] * std::pow(T::c[j], power);
  return s;
}
double AAc(int i) {
  double s = 0;
  for (int j = 0; j < 5; ++j) s += T::a[i][j] * Ac(j, 1);
  return s;
}

}  // namespace

TEST(Rk43, RowSumsEqualNodes) {
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(Ac(i, 0), T::c[i], 1e-15);
}

TEST(Rk43, OrderConditions) {
  for (const auto* b : {&T::b4, &T::b3}) {
    EXPECT_NEAR(sum_b(*b, [](int) { return 1.0; }), 1.0, 1e-15);
    EXPECT_NEAR(sum_b(*b, [](int i) { return T::c[i]; }), 0.5, 1e-15);
    EXPECT_NEAR(sum_b(*b, [](int i) { return T::c[i] * T::c[i]; }), 1.0 / 3, 1e-15);
    EXPECT_NEAR(sum_b(*b, [](int i) { return Ac(i, 1); }), 1.0 / 6, 1e-15);
  }
  // Fourth order: all four conditions hold for b4; b3 fails sum b A c^2 = 1/12.
  EXPECT_NEAR(sum_b(T::b4, [](int i) { return std::pow(T::c[i], 3); }), 0.25, 1e-15);
  EXPECT_NEAR(sum_b(T::b4, [](int i) { return T::c[i] * Ac(i, 1); }), 1.0 / 8, 1e-15);
  EXPECT_NEAR(sum_b(T::b4, [](int i) { return Ac(i, 2); }), 1.0 / 12, 1e-15);
  EXPECT_NEAR(sum_b(T::b4, [](int i) { return AAc(i); }), 1.0 / 24, 1e-15);
  EXPECT_GT(std::abs(sum_b(T::b3, [](int i) { return Ac(i, 2); }) - 1.0 / 12), 1e-3);
}

namespace {

// Nonlinear pendulum-like system y = (q, w): q' = w, w' = -sin q; fixed steps to T = 4,
// compared with a fine RK4 reference. Propagates either the 4th or the embedded 3rd order.
Eigen::Vector2d run(int n, bool third) {
  auto f = [](double, const Eigen::Vector2d& y, Eigen::Vector2d& dy) {
    dy = Eigen::Vector2d(y[1], -std::sin(y[0]));
  };
  Eigen::Vector2d y(1.2, 0.0), y4, y3, k1, k5;
  const double h = 4.0 / n;
  for (int k = 0; k < n; ++k) {
    f(k * h, y, k1);
    rk43_step(f, k * h, y, h, k1, y4, y3, k5);
    y = third ? y3 : y4;
  }
  return y;
}

}  // namespace

TEST(Rk43, GlobalConvergenceOrders) {
  const Eigen::Vector2d ref = run(20000, false);
  const double e4a = (run(40, false) - ref).norm(), e4b = (run(80, false) - ref).norm();
  const double e3a = (run(40, true) - ref).norm(), e3b = (run(80, true) - ref).norm();
  std::printf("RK4 ratio %.2f, embedded RK3 ratio %.2f\n", e4a / e4b, e3a / e3b);
  EXPECT_NEAR(e4a / e4b, 16.0, 0.15 * 16.0);
  EXPECT_NEAR(e3a / e3b, 8.0, 0.15 * 8.0);
}
