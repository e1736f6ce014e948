// Resampling uncertainty for the facet-shape fit (docs/STATISTICS.md §3.7, "additional checks"):
// a nonparametric bootstrap interval for a_fit, and a parametric-bootstrap p-value for the
// Kolmogorov-Smirnov distance (a is fitted to the same data, so the textbook KS table is wrong).
#pragma once

#include <cstdint>
#include <vector>

namespace crumple::analysis {

struct Interval {
  double lo = 0.0, hi = 0.0;
};

/// Central 95 % percentile interval of a_fit over `resamples` resamplings of the areas x (with
/// replacement; each resample is rescaled by its own mean, as the data are).
Interval bootstrap_a_interval(const std::vector<double>& x, int resamples, std::uint64_t seed);

/// p-value of the observed KS distance d_obs for n facets at shape a: fraction of samples of n
/// draws from phi(.; a) (rescaled by their mean, a refitted) whose KS distance is >= d_obs,
/// counted as (1 + hits) / (1 + resamples) so it is never exactly 0.
double ks_pvalue_parametric(std::size_t n, double a, double d_obs, int resamples,
                            std::uint64_t seed);

/// n draws of xi from phi(.; a): g ~ Gamma(a, 1), xi = g^2 / (a(a+1)).
std::vector<double> sample_phi(std::size_t n, double a, std::uint64_t seed);

}  // namespace crumple::analysis
