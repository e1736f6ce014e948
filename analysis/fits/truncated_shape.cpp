// Left-truncated facet-area law; see truncated_shape.hpp.
#include "analysis/fits/truncated_shape.hpp"

#include "analysis/fits/facet_shape.hpp"
#include "analysis/fits/incomplete_gamma.hpp"
#include "analysis/fits/minimize_1d.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace crumple::analysis {
namespace {

// Scan points over ln a and over ln theta before Brent's method refines the best one.
constexpr int kScanA = 30, kScanTheta = 24;
constexpr double kThetaRange = 6.0;  // ln theta searched within +-6 of the untruncated estimate
// Stands for -ln L where the law puts no mass above the floor: finite, so Brent's parabolas
// through it stay finite.
constexpr double kHuge = 1e300;

/// What the likelihood needs of the data: n, sum ln y, sum y, y_min (y = sqrt x).
struct Sufficient {
  double n = 0, sum_log_y = 0, sum_y = 0, y_min = 0;
};

Sufficient sufficient(const std::vector<double>& x, double x_min) {
  Sufficient s;
  s.y_min = std::sqrt(x_min);
  for (double v : x)
    if (v >= x_min) {
      const double y = std::sqrt(v);
      s.n += 1, s.sum_log_y += std::log(y), s.sum_y += y;
    }
  return s;
}

double neg_loglik(const Sufficient& s, double a, double theta) {
  const double q = gamma_q(a, s.y_min / theta);
  if (!(q > 0)) return kHuge;
  return -((a - 1.0) * s.sum_log_y - s.sum_y / theta -
           s.n * (a * std::log(theta) + std::lgamma(a) + std::log(q)));
}

/// Best ln theta at shape a, and -ln L there.
std::pair<double, double> profile_theta(const Sufficient& s, double a, bool& at_bound) {
  const double v0 = std::log(s.sum_y / (s.n * a));
  const auto f = [&](double v) { return neg_loglik(s, a, std::exp(v)); };
  const double v = scan_minimize(f, v0 - kThetaRange, v0 + kThetaRange, kScanTheta, at_bound);
  return {v, f(v)};
}

TruncatedShapeFit fit(const Sufficient& s, double x_min) {
  if (!(x_min > 0)) throw std::invalid_argument("fit_truncated_shape: the floor must be positive");
  if (s.n < 5)
    throw std::invalid_argument("fit_truncated_shape: need at least 5 areas at or above the floor");
  bool theta_bound = false;
  const auto f = [&](double u) { return profile_theta(s, std::exp(u), theta_bound).second; };
  bool a_bound = false;
  const double u = scan_minimize(f, std::log(kTruncAMin), std::log(kTruncAMax), kScanA, a_bound);
  TruncatedShapeFit r;
  r.a = std::exp(u);
  const auto [v, nll] = profile_theta(s, r.a, theta_bound);
  const double theta = std::exp(v);
  r.mean_x = theta * theta * r.a * (r.a + 1.0);
  r.x_min = x_min;
  r.n = static_cast<std::size_t>(s.n);
  r.loglik = -nll;
  r.share_below = gamma_p(r.a, s.y_min / theta);
  r.at_bound = a_bound || theta_bound;
  return r;
}

double theta_of(const TruncatedShapeFit& f) { return std::sqrt(f.mean_x / (f.a * (f.a + 1.0))); }

}  // namespace

TruncatedShapeFit fit_truncated_shape(const std::vector<double>& x, double x_min) {
  return fit(sufficient(x, x_min), x_min);
}

double truncated_cdf(double x, const TruncatedShapeFit& f) {
  if (x <= f.x_min) return 0.0;
  const double theta = theta_of(f);
  const double q_min = gamma_q(f.a, std::sqrt(f.x_min) / theta);
  return (q_min - gamma_q(f.a, std::sqrt(x) / theta)) / q_min;
}

double truncated_ks_distance(const std::vector<double>& x, const TruncatedShapeFit& f) {
  std::vector<double> above;
  for (double v : x)
    if (v >= f.x_min) above.push_back(v);
  std::sort(above.begin(), above.end());
  return ks_distance_sorted(above, [&f](double v) { return truncated_cdf(v, f); });
}

std::vector<double> sample_truncated(std::size_t n, const TruncatedShapeFit& f,
                                     std::uint64_t seed) {
  const double theta = theta_of(f), y_min = std::sqrt(f.x_min);
  if (!(gamma_q(f.a, y_min / theta) >= 1e-4))
    throw std::runtime_error("sample_truncated: the law leaves almost no mass above the floor");
  std::mt19937_64 rng(seed);
  std::gamma_distribution<double> g(f.a, theta);
  std::vector<double> x;
  x.reserve(n);
  while (x.size() < n) {
    const double y = g(rng);
    if (y >= y_min) x.push_back(y * y);
  }
  return x;
}

double truncated_ks_pvalue(const TruncatedShapeFit& f, double d_obs, int resamples,
                           std::uint64_t seed) {
  if (f.n < 5 || resamples < 1) throw std::invalid_argument("truncated ks p-value: too few values");
  int hits = 0;
  for (int b = 0; b < resamples; ++b) {
    const auto x = sample_truncated(f.n, f, seed + static_cast<std::uint64_t>(b));
    if (truncated_ks_distance(x, fit_truncated_shape(x, f.x_min)) >= d_obs) ++hits;
  }
  return (1.0 + hits) / (1.0 + resamples);
}

}  // namespace crumple::analysis
