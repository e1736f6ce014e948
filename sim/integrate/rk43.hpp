// Explicit adaptive Runge-Kutta: the classical fourth-order method with an embedded
// third-order solution that reuses a first-same-as-last stage (paper §3.4).
//
// Stages (c = 0, 1/2, 1/2, 1, 1):
//   k1 = f(t, y), k2 = f(t + h/2, y + h/2 k1), k3 = f(t + h/2, y + h/2 k2),
//   k4 = f(t + h, y + h k3),
//   y4 = y + h (k1 + 2 k2 + 2 k3 + k4) / 6          (classical RK4, order 4, propagated),
//   k5 = f(t + h, y4)                                (= k1 of the next step),
//   y3 = y + h (k1 + 2 k2 + 2 k3 + k5) / 6          (embedded, order 3).
// Derivation of the embedded weights: write bhat = b + d with b the RK4 weights. The four
// third-order conditions (sum b = 1, sum b c = 1/2, sum b c^2 = 1/3, sum b A c = 1/6) leave
// exactly d = (0, 0, 0, delta, -delta); any delta != 0 breaks the fourth-order condition
// sum b A c^2 = 1/12 (by -delta/12), so the embedded solution is exactly of order 3. We take
// delta = -1/6, which removes k4 from y3. The error estimate is y4 - y3 = h (k4 - k5) / 6, a
// local error of order h^4 (tests/integrate/test_rk43.cpp checks all conditions).
#pragma once

#include "sim/core/parallel_assign.hpp"

#include <array>

namespace crumple {

struct Rk43Tableau {
  static constexpr std::array<double, 5> c{0.0, 0.5, 0.5, 1.0, 1.0};
  /// a[i][j], stage i from stage j < i (row 4 = the FSAL stage, equal to the RK4 weights).
  static constexpr std::array<std::array<double, 5>, 5> a{{{0, 0, 0, 0, 0},
                                                           {0.5, 0, 0, 0, 0},
                                                           {0, 0.5, 0, 0, 0},
                                                           {0, 0, 1.0, 0, 0},
                                                           {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6, 0}}};
  static constexpr std::array<double, 5> b4{1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6, 0.0};
  static constexpr std::array<double, 5> b3{1.0 / 6, 1.0 / 3, 1.0 / 3, 0.0, 1.0 / 6};
};

/// One step of the pair for y' = f(t, y) with any Eigen vector type Y.
/// k1 = f(t, y) on entry; on return y4, y3 and k5 = f(t + h, y4).
template <class F, class Y>
void rk43_step(F&& f, double t, const Y& y, double h, const Y& k1, Y& y4, Y& y3, Y& k5) {
  Y k2, k3, k4, tmp;
  parallel_assign(tmp, y + (0.5 * h) * k1);
  f(t + 0.5 * h, tmp, k2);
  parallel_assign(tmp, y + (0.5 * h) * k2);
  f(t + 0.5 * h, tmp, k3);
  parallel_assign(tmp, y + h * k3);
  f(t + h, tmp, k4);
  parallel_assign(y4, y + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4));
  f(t + h, y4, k5);
  parallel_assign(y3, y4 + (h / 6.0) * (k5 - k4));
}

}  // namespace crumple
