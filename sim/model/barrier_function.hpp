// The one-sided barrier shared by the fold barrier (sim/contact/fold_barrier.hpp, in the fold
// opening) and the area barrier (area_barrier.hpp, in the squared area ratio):
//     E(x) = K u^3 / (x0^2 (x + delta)),   u = x0 - x,   delta = 0.02 x0,   for x < x0,
// zero above x0. It is C^2 at the onset x0 and finite at x = 0 (E(0) = 50 K), so every force
// stays finite when a step lands at a complete fold or a collapsed triangle.
#pragma once

namespace crumple {

/// E and its first two derivatives in x.
struct BarrierValue {
  double e, d1, d2;
};

/// The barrier at x < x0 (callers test the onset themselves).
inline BarrierValue cubic_barrier(double K, double x0, double x) {
  constexpr double kDelta = 0.02;
  const double u = x0 - x, c = K / (x0 * x0), q = x + kDelta * x0;
  return {c * u * u * u / q, c * (-3.0 * u * u / q - u * u * u / (q * q)),
          c * (6.0 * u / q + 6.0 * u * u / (q * q) + 2.0 * u * u * u / (q * q * q))};
}

}  // namespace crumple
