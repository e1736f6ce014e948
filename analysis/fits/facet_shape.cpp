// Facet-area law and its shape estimators; see facet_shape.hpp.
#include "analysis/fits/facet_shape.hpp"

#include "analysis/fits/incomplete_gamma.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace crumple::analysis {
namespace {

/// Mean log-likelihood per sample of phi(.; a), using precomputed means of log xi and sqrt xi.
double mean_loglik(double a, double mean_log_xi, double mean_sqrt_xi) {
  const double k = a * (a + 1.0);
  // log phi = log k - log 2 - lgamma(a) + (a/2 - 1)(log k + log xi) - sqrt(k) sqrt(xi)
  return std::log(k) - std::log(2.0) - std::lgamma(a) + (0.5 * a - 1.0) * (std::log(k) + mean_log_xi) -
         std::sqrt(k) * mean_sqrt_xi;
}

}  // namespace

double phi_density(double xi, double a) {
  if (xi <= 0) return 0.0;
  const double k = a * (a + 1.0), z = k * xi;
  return std::exp(std::log(k) - std::log(2.0) - std::lgamma(a) + (0.5 * a - 1.0) * std::log(z) -
                  std::sqrt(z));
}

double phi_cdf(double xi, double a) {
  return xi <= 0 ? 0.0 : gamma_p(a, std::sqrt(a * (a + 1.0) * xi));
}

double fit_a_mle(const std::vector<double>& xi) {
  if (xi.size() < 2) throw std::invalid_argument("fit_a_mle: need at least 2 facets");
  double ml = 0.0, ms = 0.0;
  for (double v : xi) {
    if (!(v > 0)) throw std::invalid_argument("fit_a_mle: scaled areas must be positive");
    ml += std::log(v);
    ms += std::sqrt(v);
  }
  ml /= static_cast<double>(xi.size());
  ms /= static_cast<double>(xi.size());
  auto f = [&](double u) { return mean_loglik(std::exp(u), ml, ms); };
  // Coarse scan on log a, then golden section in the bracket around the best grid point.
  const double lo = std::log(1e-3), hi = std::log(1e3);
  const int n = 60;
  int best = 0;
  double fbest = f(lo);
  for (int i = 1; i <= n; ++i) {
    const double v = f(lo + (hi - lo) * i / n);
    if (v > fbest) fbest = v, best = i;
  }
  double a = lo + (hi - lo) * std::max(best - 1, 0) / n;
  double b = lo + (hi - lo) * std::min(best + 1, n) / n;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a), fc = f(c), fd = f(d);
  while (b - a > 1e-10) {
    if (fc > fd) {
      b = d, d = c, fd = fc, c = b - g * (b - a), fc = f(c);
    } else {
      a = c, c = d, fc = fd, d = a + g * (b - a), fd = f(d);
    }
  }
  return std::exp(0.5 * (a + b));
}

double a_moment(const std::vector<double>& xi) {
  if (xi.size() < 2) throw std::invalid_argument("a_moment: need at least 2 facets");
  const double n = static_cast<double>(xi.size());
  const double m = std::accumulate(xi.begin(), xi.end(), 0.0) / n;
  double v = 0.0;
  for (double x : xi) v += (x - m) * (x - m);
  v /= n - 1.0;
  if (!(v > 0)) throw std::invalid_argument("a_moment: zero variance");
  return ((4.0 - v) + std::sqrt((v - 4.0) * (v - 4.0) + 24.0 * v)) / (2.0 * v);
}

double a_universal(double s, double tau) {
  if (!(s > 0)) throw std::invalid_argument("a_universal: s must be positive");
  // (a+1)/a^3 falls monotonically from +inf to 0, so bisection on log a always converges.
  const double target = tau * tau * s;
  double lo = std::log(1e-6), hi = std::log(1e6);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi), a = std::exp(mid);
    ((a + 1.0) / (a * a * a) > target ? lo : hi) = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

double ks_distance(std::vector<double> xi, double a) {
  std::sort(xi.begin(), xi.end());
  return ks_distance_sorted(xi, [a](double v) { return phi_cdf(v, a); });
}

std::vector<double> scaled_areas(const std::vector<double>& x) {
  if (x.empty()) return {};
  const double s = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
  std::vector<double> xi(x.size());
  std::transform(x.begin(), x.end(), xi.begin(), [s](double v) { return v / s; });
  return xi;
}

}  // namespace crumple::analysis
