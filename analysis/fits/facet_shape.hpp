// The fragmentation-model facet-area law and estimators of its shape a (docs/STATISTICS.md §3.3,
// §3.4, §3.7). With xi = x / <x> the scaled facet area,
//   phi(xi; a) = a(a+1) / (2 Gamma(a)) z^{a/2-1} exp(-sqrt z),  z = a(a+1) xi,
//   F(xi; a)   = P(a, sqrt(a(a+1) xi)),
// i.e. sqrt(a(a+1) xi) ~ Gamma(a, 1): the square root of the area is gamma distributed with the
// scale tied to the mean area.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace crumple::analysis {

/// Density phi(xi; a) (docs/STATISTICS.md §3.3).
double phi_density(double xi, double a);

/// CDF F(xi; a) = P(a, sqrt(a(a+1) xi)).
double phi_cdf(double xi, double a);

/// Maximum-likelihood a for scaled areas xi under phi(xi; a), scale fixed by <xi> = 1 (the
/// one-parameter fit of docs/STATISTICS.md §3.7 step 5). Searches a in [1e-3, 1e3] (golden section
/// on log a after a coarse scan). Needs at least 2 values, all > 0.
double fit_a_mle(const std::vector<double>& xi);

/// Moment estimator from the sample variance v of xi, Var(xi) = (4a+6)/(a(a+1)):
/// a = [(4 - v) + sqrt((v - 4)^2 + 24 v)] / (2 v) (docs/STATISTICS.md §3.3).
double a_moment(const std::vector<double>& xi);

/// "Universal" a from the mean facet area s (fraction of the sheet): the root of
/// (a+1)/a^3 = tau^2 s (docs/STATISTICS.md §3.4), tau = 24.04 for the Mylar data.
inline constexpr double kTau = 24.04;
double a_universal(double s, double tau = kTau);

/// Kolmogorov-Smirnov distance sup |F_emp(xi) - F(xi; a)|.
double ks_distance(std::vector<double> xi, double a);

/// sup |F_emp - F| of ascending values against the CDF F (both sides of each step).
template <class Cdf>
double ks_distance_sorted(const std::vector<double>& sorted, Cdf F) {
  const double n = static_cast<double>(sorted.size());
  double d = 0.0;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    const double f = F(sorted[i]);
    d = std::max({d, static_cast<double>(i + 1) / n - f, f - static_cast<double>(i) / n});
  }
  return d;
}

/// Scales areas to xi = x / mean(x).
std::vector<double> scaled_areas(const std::vector<double>& x);

}  // namespace crumple::analysis
