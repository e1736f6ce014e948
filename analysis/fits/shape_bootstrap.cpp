// Bootstrap interval and parametric KS p-value; see shape_bootstrap.hpp.
#include "analysis/fits/shape_bootstrap.hpp"

#include "analysis/fits/facet_shape.hpp"

#include <algorithm>
#include <random>
#include <stdexcept>

namespace crumple::analysis {

Interval bootstrap_a_interval(const std::vector<double>& x, int resamples, std::uint64_t seed) {
  if (x.size() < 2 || resamples < 2) throw std::invalid_argument("bootstrap: too few values");
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, x.size() - 1);
  std::vector<double> a(static_cast<std::size_t>(resamples)), r(x.size());
  for (auto& ai : a) {
    for (auto& v : r) v = x[pick(rng)];
    ai = fit_a_mle(scaled_areas(r));
  }
  std::sort(a.begin(), a.end());
  auto q = [&](double f) { return a[static_cast<std::size_t>(f * static_cast<double>(a.size() - 1) + 0.5)]; };
  return {q(0.025), q(0.975)};
}

std::vector<double> sample_phi(std::size_t n, double a, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::gamma_distribution<double> g(a, 1.0);
  std::vector<double> xi(n);
  for (auto& v : xi) {
    const double t = g(rng);
    v = t * t / (a * (a + 1.0));
  }
  return xi;
}

double ks_pvalue_parametric(std::size_t n, double a, double d_obs, int resamples,
                            std::uint64_t seed) {
  if (n < 2 || resamples < 1) throw std::invalid_argument("ks p-value: too few values");
  int hits = 0;
  for (int b = 0; b < resamples; ++b) {
    auto xi = scaled_areas(sample_phi(n, a, seed + static_cast<std::uint64_t>(b)));
    // Tiny gamma draws can underflow to 0 at small a; the data never hold empty facets.
    for (auto& v : xi) v = std::max(v, 1e-300);
    if (ks_distance(xi, fit_a_mle(xi)) >= d_obs) ++hits;
  }
  return (1.0 + hits) / (1.0 + resamples);
}

}  // namespace crumple::analysis
