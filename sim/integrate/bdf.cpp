// Variable-step BDF coefficients, predictor weights and error constant (bdf.hpp).
#include "sim/integrate/bdf.hpp"

#include <limits>
#include <stdexcept>

namespace crumple {

BdfCoefficients bdf_coefficients(const std::vector<double>& times) {
  const int s = static_cast<int>(times.size()) - 1;
  if (s < 1) throw std::invalid_argument("bdf_coefficients: need at least two times");
  const double t0 = times[0];
  // L_0'(t_0) = sum_{m>=1} 1 / (t_0 - t_m).
  double l0 = 0.0;
  for (int m = 1; m <= s; ++m) l0 += 1.0 / (t0 - times[m]);
  BdfCoefficients c;
  c.order = s;
  c.h = t0 - times[1];
  c.beta = 1.0 / (l0 * c.h);
  c.alpha.resize(s);
  for (int j = 1; j <= s; ++j) {
    // L_j'(t_0): the factor (t - t_0) of L_j vanishes at t_0, so only its derivative survives.
    double num = 1.0, den = times[j] - t0;
    for (int m = 1; m <= s; ++m) {
      if (m == j) continue;
      num *= t0 - times[m];
      den *= times[j] - times[m];
    }
    c.alpha[j - 1] = (num / den) / l0;
  }
  return c;
}

std::vector<double> lagrange_weights(const std::vector<double>& nodes, double t) {
  const std::size_t n = nodes.size();
  std::vector<double> w(n, 1.0);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t m = 0; m < n; ++m)
      if (m != j) w[j] *= (t - nodes[m]) / (nodes[j] - nodes[m]);
  return w;
}

double bdf_error_factor(const std::vector<double>& times) {
  const int s = static_cast<int>(times.size()) - 2;
  if (s < 1) throw std::invalid_argument("bdf_error_factor: need order + 2 times");
  const double t0 = times[0];
  double l0 = 0.0, prod_s = 1.0;
  for (int m = 1; m <= s; ++m) {
    l0 += 1.0 / (t0 - times[m]);
    prod_s *= t0 - times[m];
  }
  const double cp = prod_s * (t0 - times[s + 1]);
  const double cc = -prod_s / l0;
  return cc / (cp - cc);
}

double bdf_growth_limit(int order) {
  // Ratios at which the extraneous roots on a constant-ratio grid have modulus 0.9 (bdf.hpp),
  // rounded down.
  switch (order) {
    case 1: return std::numeric_limits<double>::infinity();
    case 2: return 2.2;
    case 3: return 1.5;
    default: return 1.22;
  }
}

}  // namespace crumple
