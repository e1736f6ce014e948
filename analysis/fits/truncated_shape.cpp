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

// Scan points over ln a, and per unit of ln theta, before Brent's method refines the best one.
constexpr int kScanA = 30;
constexpr double kScanThetaPerUnit = 4.0;
constexpr double kThetaRange = 6.0;  // ln theta searched from 6 below the untruncated estimate...
constexpr double kTailMargin = 3.0;  // ...or 3 below the tail's scale, to 6 above the former
// Below this share of the law's mass above the floor the sampler inverts the CDF.
constexpr double kRejectionMinShare = 0.05;
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
  // ln Q directly: Q itself underflows far in the tail, where the likelihood is still finite.
  const double lq = log_gamma_q(a, s.y_min / theta);
  const double nll = -((a - 1.0) * s.sum_log_y - s.sum_y / theta -
                       s.n * (a * std::log(theta) + std::lgamma(a) + lq));
  return std::isfinite(nll) ? nll : kHuge;
}

/// Best ln theta at shape a, and -ln L there. Deep in the tail (y_min many theta) the scale is
/// set by the mean excess over the floor, not by mean(y) / a, so the range reaches below both.
std::pair<double, double> profile_theta(const Sufficient& s, double a, bool& at_bound) {
  const double mean_y = s.sum_y / s.n;
  const double v0 = std::log(mean_y / a);
  const double excess = std::max(mean_y - s.y_min, 1e-12 * mean_y);
  const double lo = std::min(v0 - kThetaRange, std::log(excess / (a + 1.0)) - kTailMargin);
  const double hi = v0 + kThetaRange;
  const int K = static_cast<int>(std::ceil(kScanThetaPerUnit * (hi - lo)));
  const auto f = [&](double v) { return neg_loglik(s, a, std::exp(v)); };
  const double v = scan_minimize(f, lo, hi, K, at_bound);
  return {v, f(v)};
}

/// splitmix64: a well-mixed 64-bit hash, so that resample b of one seed and resample b' of a
/// nearby seed draw unrelated streams.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

TruncatedShapeFit fit(const Sufficient& s, double x_min) {
  if (!(x_min > 0)) throw std::invalid_argument("fit_truncated_shape: the floor must be positive");
  if (s.n < 5)
    throw std::invalid_argument("fit_truncated_shape: need at least 5 areas at or above the floor");
  bool theta_bound = false;
  const auto f = [&](double u) { return profile_theta(s, std::exp(u), theta_bound).second; };
  bool a_bound = false;
  const double u_lo = std::log(kTruncAMin), u_hi = std::log(kTruncAMax);
  const double u = scan_minimize(f, u_lo, u_hi, kScanA, a_bound);
  TruncatedShapeFit r;
  r.a = std::exp(u);
  const auto [v, nll] = profile_theta(s, r.a, theta_bound);
  if (!(nll < 0.5 * kHuge))
    throw std::runtime_error("fit_truncated_shape: no law in range gives the data a finite likelihood");
  const double theta = std::exp(v);
  r.mean_x = theta * theta * r.a * (r.a + 1.0);
  r.x_min = x_min;
  r.n = static_cast<std::size_t>(s.n);
  r.loglik = -nll;
  r.share_below = gamma_p(r.a, s.y_min / theta);
  if (a_bound)
    r.edge = u - u_lo < u_hi - u ? FitEdge::a_min : FitEdge::a_max;
  else if (theta_bound)
    r.edge = FitEdge::theta;
  return r;
}

double theta_of(const TruncatedShapeFit& f) { return std::sqrt(f.mean_x / (f.a * (f.a + 1.0))); }

}  // namespace

const char* fit_edge_name(FitEdge e) {
  switch (e) {
    case FitEdge::a_min: return "a_min";
    case FitEdge::a_max: return "a_max";
    case FitEdge::theta: return "theta";
    case FitEdge::none: break;
  }
  return "";
}

TruncatedShapeFit fit_truncated_shape(const std::vector<double>& x, double x_min) {
  return fit(sufficient(x, x_min), x_min);
}

namespace {

/// The cut CDF with ln Q(a, t_min) computed once: 1 - Q(a, t) / Q(a, t_min), in logs so that it
/// holds where Q underflows.
struct CutCdf {
  double a, theta, x_min, lq_min;
  explicit CutCdf(const TruncatedShapeFit& f)
      : a(f.a), theta(theta_of(f)), x_min(f.x_min),
        lq_min(log_gamma_q(f.a, std::sqrt(f.x_min) / theta)) {}
  double operator()(double x) const {
    return x <= x_min ? 0.0 : -std::expm1(log_gamma_q(a, std::sqrt(x) / theta) - lq_min);
  }
};

}  // namespace

double truncated_cdf(double x, const TruncatedShapeFit& f) { return CutCdf(f)(x); }

double truncated_ks_distance(const std::vector<double>& x, const TruncatedShapeFit& f) {
  std::vector<double> above;
  for (double v : x)
    if (v >= f.x_min) above.push_back(v);
  std::sort(above.begin(), above.end());
  return ks_distance_sorted(above, CutCdf(f));
}

std::vector<double> sample_truncated(std::size_t n, const TruncatedShapeFit& f,
                                     std::uint64_t seed) {
  const double theta = theta_of(f), t_min = std::sqrt(f.x_min) / theta;
  const double lq_min = log_gamma_q(f.a, t_min);
  std::mt19937_64 rng(seed);
  std::vector<double> x;
  x.reserve(n);
  if (std::exp(lq_min) >= kRejectionMinShare) {
    std::gamma_distribution<double> g(f.a, 1.0);
    while (x.size() < n) {
      const double t = g(rng);
      if (t >= t_min) x.push_back(theta * theta * t * t);
    }
    return x;
  }
  // Inverse CDF: t with Q(a, t) = Q(a, t_min) (1 - u), by bisection on ln Q, which falls with t.
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  while (x.size() < n) {
    const double target = lq_min + std::log1p(-uniform(rng));
    double lo = t_min, hi = t_min + 1.0;
    while (log_gamma_q(f.a, hi) > target) lo = hi, hi = t_min + 2.0 * (hi - t_min);
    for (int i = 0; i < 100 && hi - lo > 1e-13 * hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      (log_gamma_q(f.a, mid) > target ? lo : hi) = mid;
    }
    const double t = 0.5 * (lo + hi);
    x.push_back(theta * theta * t * t);
  }
  return x;
}

double truncated_ks_pvalue(const TruncatedShapeFit& f, double d_obs, int resamples,
                           std::uint64_t seed) {
  if (f.n < 5 || resamples < 1) throw std::invalid_argument("truncated ks p-value: too few values");
  int hits = 0;
  for (int b = 0; b < resamples; ++b) {
    const auto x = sample_truncated(f.n, f, mix(seed ^ mix(static_cast<std::uint64_t>(b))));
    if (truncated_ks_distance(x, fit_truncated_shape(x, f.x_min)) >= d_obs) ++hits;
  }
  return (1.0 + hits) / (1.0 + resamples);
}

}  // namespace crumple::analysis
