// dst = expr for long Eigen vectors, evaluated by all OpenMP threads.
//
// Eigen evaluates coefficient-wise expressions on one thread. In an explicit step the state
// vectors (positions, velocities, plastic curvatures: 9 n entries) are combined a dozen times
// between force evaluations; done serially, the other threads wait at the next parallel
// region. Each entry is computed by the same expression whatever thread computes it, so the
// result is bit-identical to the serial assignment.
#pragma once

#include <Eigen/Core>

#include <algorithm>

namespace crumple {

/// Below this length the fork is dearer than the work.
inline constexpr Eigen::Index kParallelAssignMin = 16384;

template <class Dst, class Expr>
void parallel_assign(Dst& dst, const Expr& expr) {
  const Eigen::Index n = expr.size();
  if (n < kParallelAssignMin) {
    dst = expr;
    return;
  }
  dst.resize(n);
  constexpr Eigen::Index chunk = 4096;
  const Eigen::Index chunks = (n + chunk - 1) / chunk;
#pragma omp parallel for schedule(static)
  for (Eigen::Index k = 0; k < chunks; ++k) {
    const Eigen::Index b = k * chunk, len = std::min(chunk, n - b);
    dst.segment(b, len) = expr.segment(b, len);
  }
}

}  // namespace crumple
