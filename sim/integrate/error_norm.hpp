// Weighted root-mean-square norms used by the error tests and the Newton stopping rule: each
// component e_i is measured against atol + rtol |y_i|, so a value of 1 means "at tolerance".
#pragma once

#include "sim/core/types.hpp"

#include <cmath>

namespace crumple {

/// sum_i (e_i / (atol + rtol |y_i|))^2
inline double weighted_sq_sum(const VecX& e, const VecX& y, double atol, double rtol) {
  double s = 0.0;
  for (Eigen::Index i = 0; i < e.size(); ++i) {
    const double w = e[i] / (atol + rtol * std::abs(y[i]));
    s += w * w;
  }
  return s;
}

/// Weighted RMS over two blocks (x and p, say) measured with the same tolerances.
inline double wrms2(const VecX& e1, const VecX& y1, const VecX& e2, const VecX& y2, double atol,
                    double rtol) {
  const double n = static_cast<double>(e1.size() + e2.size());
  if (n == 0) return 0.0;
  return std::sqrt((weighted_sq_sum(e1, y1, atol, rtol) + weighted_sq_sum(e2, y2, atol, rtol)) / n);
}

}  // namespace crumple
