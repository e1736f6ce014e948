// Tests of the facet law cut at the resolution floor (analysis/fits/truncated_shape.hpp): the
// fit recovers a known law from samples cut at a floor, reaches the likelihood's maximum as an
// independent brute-force search over (a, s) finds it with the law written through
// phi_density and phi_cdf, deep in the tail too, a pure power-law tail stops on the small-a edge,
// its CDF is the cut phi, and the bootstrap KS test holds its level under the law and tells the
// law from other shapes.
#include "analysis/fits/facet_shape.hpp"
#include "analysis/fits/incomplete_gamma.hpp"
#include "analysis/fits/shape_bootstrap.hpp"
#include "analysis/fits/truncated_shape.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace crumple::analysis;

namespace {

/// Areas from phi(.; a) with mean s (sample_phi is the independent sampler of xi).
std::vector<double> areas(std::size_t n, double a, double s, std::uint64_t seed) {
  auto xi = sample_phi(n, a, seed);
  for (auto& v : xi) v *= s;
  return xi;
}

/// The q-quantile of x.
double quantile(std::vector<double> x, double q) {
  std::sort(x.begin(), x.end());
  return x[static_cast<std::size_t>(q * static_cast<double>(x.size() - 1))];
}

/// ln L of the areas at or above x_min under phi(x/s; a)/s cut there, written with the
/// one-parameter law's own functions (not the fit's gamma form in sqrt x).
double loglik_phi(const std::vector<double>& x, double x_min, double a, double s) {
  const double keep = 1.0 - phi_cdf(x_min / s, a);
  double L = 0;
  for (double v : x)
    if (v >= x_min) L += std::log(phi_density(v / s, a) / s / keep);
  return L;
}

}  // namespace

TEST(TruncatedShape, RecoversKnownLawBelowAFloor) {
  for (double a : {0.6, 1.5, 4.0, 12.0}) {
    const double s = 2e-3;
    const auto x = areas(20000, a, s, 31);
    const double x_min = quantile(x, 0.4);  // the floor cuts 40 % of the facets
    const auto f = fit_truncated_shape(x, x_min);
    std::printf("a = %.2f: truncated fit a %.4f, s/s_true %.4f, share below %.3f (%zu above)\n", a,
                f.a, f.mean_x / s, f.share_below, f.n);
    EXPECT_NEAR(f.a / a, 1.0, 0.08) << a;
    EXPECT_NEAR(f.mean_x / s, 1.0, 0.08) << a;
    EXPECT_NEAR(f.share_below, 0.4, 0.03) << a;
    EXPECT_EQ(f.n, static_cast<std::size_t>(std::count_if(x.begin(), x.end(),
                                                           [&](double v) { return v >= x_min; })));
    EXPECT_EQ(f.edge, FitEdge::none);
    // Cutting the sample and fitting the whole law would not do: the one-parameter fit of the
    // areas above the floor, rescaled by their own mean, sees a narrower law.
    std::vector<double> above;
    for (double v : x)
      if (v >= x_min) above.push_back(v);
    EXPECT_GT(fit_a_mle(scaled_areas(above)) / a, 1.3) << a;
  }
}

TEST(TruncatedShape, ReachesTheMaximumAnIndependentSearchFinds) {
  const auto x = areas(400, 0.9, 1e-3, 7);
  const double x_min = quantile(x, 0.3);
  const auto f = fit_truncated_shape(x, x_min);
  const double L_fit = loglik_phi(x, x_min, f.a, f.mean_x);
  // A brute-force grid in (ln a, ln s) around the fit, over the same likelihood written
  // differently (it differs from the fit's by a constant, the Jacobian of y = sqrt x).
  double best = -INFINITY, a_best = 0, s_best = 0;
  for (int i = -40; i <= 40; ++i)
    for (int j = -40; j <= 40; ++j) {
      const double a = f.a * std::exp(0.02 * i), s = f.mean_x * std::exp(0.03 * j);
      const double L = loglik_phi(x, x_min, a, s);
      if (L > best) best = L, a_best = a, s_best = s;
    }
  EXPECT_GE(L_fit, best - 1e-6);
  EXPECT_NEAR(a_best / f.a, 1.0, 0.021);
  EXPECT_NEAR(s_best / f.mean_x, 1.0, 0.031);
  // The likelihood the fit reports is this one up to that constant.
  double jac = 0;  // sum ln(2 sqrt x): p_x(x) = p_y(sqrt x) / (2 sqrt x)
  for (double v : x)
    if (v >= x_min) jac += std::log(2.0 * std::sqrt(v));
  EXPECT_NEAR(f.loglik - jac, L_fit, 1e-6 * std::abs(L_fit));
}

TEST(TruncatedShape, DeepInTheTail) {
  // A floor that leaves 1e-3 of the law above it: the sampler inverts the CDF, and the scale's
  // optimum lies far below the untruncated estimate mean(y) / a. So far in the tail the data no
  // longer pin the shape (20000 areas from a = 1.5 are fitted as well or better by a ~ 0.3), so
  // the test is that the fit reaches at least the law's own likelihood and stays interior.
  TruncatedShapeFit law;
  law.a = 1.5, law.mean_x = 1e-3;
  const double theta = std::sqrt(law.mean_x / (law.a * (law.a + 1.0)));
  // Q(1.5, t) = 1e-3 at t = 8.85 (the tail of Gamma(1.5, 1)).
  law.x_min = (8.85 * theta) * (8.85 * theta);
  const auto x = sample_truncated(20000, law, 17);
  EXPECT_GE(*std::min_element(x.begin(), x.end()), law.x_min);
  EXPECT_LT(truncated_ks_distance(x, law), 1.63 / std::sqrt(20000.0));
  const auto f = fit_truncated_shape(x, law.x_min);
  const double L_law = loglik_phi(x, law.x_min, law.a, law.mean_x);
  const double L_fit = loglik_phi(x, law.x_min, f.a, f.mean_x);
  std::printf("deep tail: a %.3f (1.5), s/s_true %.3f; ln L at the fit - at the law %.3f\n", f.a,
              f.mean_x / law.mean_x, L_fit - L_law);
  EXPECT_EQ(f.edge, FitEdge::none);
  EXPECT_GE(L_fit, L_law - 1e-6 * std::abs(L_law));
  EXPECT_LT(truncated_ks_distance(x, f), 1.63 / std::sqrt(20000.0));
  // Far past where Q underflows (ln Q ~ -900 at the floor), the fit still reaches the law's own
  // likelihood, written here in sqrt x with ln Q from log_gamma_q.
  TruncatedShapeFit far = law;
  far.x_min = (900.0 * theta) * (900.0 * theta);
  const auto y = sample_truncated(500, far, 4);
  const auto g = fit_truncated_shape(y, far.x_min);
  double L_far = 0;
  for (double v : y)
    L_far += (law.a - 1.0) * std::log(std::sqrt(v)) - std::sqrt(v) / theta - law.a * std::log(theta) -
             std::lgamma(law.a) - log_gamma_q(law.a, std::sqrt(far.x_min) / theta);
  EXPECT_TRUE(std::isfinite(L_far));
  EXPECT_GE(g.loglik, L_far - 1e-6 * std::abs(L_far));
}

TEST(TruncatedShape, APureTailStopsOnTheSmallAEdge) {
  // Areas with a power-law density x^-2.5 above the floor fall faster at small x than any
  // member with a > 0 (whose density in sqrt x rises or holds as y^(a-1)): the fit stops at a_min.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> x(800);
  for (auto& v : x) v = 1e-3 * std::pow(1.0 - u(rng), -1.0 / 1.5);
  const auto f = fit_truncated_shape(x, 1e-3);
  EXPECT_EQ(f.edge, FitEdge::a_min);
  EXPECT_STREQ(fit_edge_name(f.edge), "a_min");
  EXPECT_NEAR(f.a, kTruncAMin, 1e-9);
}

TEST(TruncatedShape, BootstrapRejectsAtItsLevelUnderTheLaw) {
  // Under the null, p <= 0.2 in about a fifth of datasets: 60 datasets give 12 +- 3.1; a
  // bootstrap without the refit, or with one resample repeated, leaves this range.
  int small = 0;
  for (int k = 0; k < 60; ++k) {
    const auto x = areas(150, 1.0, 1e-3, 1000 + k);
    const double x_min = quantile(x, 0.3);
    const auto f = fit_truncated_shape(x, x_min);
    small += truncated_ks_pvalue(f, truncated_ks_distance(x, f), 40, 77 + k) <= 0.2;
  }
  std::printf("p <= 0.2 in %d of 60 null datasets\n", small);
  EXPECT_GE(small, 4);
  EXPECT_LE(small, 22);
}

TEST(TruncatedShape, CdfIsTheCutLaw) {
  TruncatedShapeFit f;
  f.a = 1.3, f.mean_x = 0.01, f.x_min = 0.004;
  const double F0 = phi_cdf(f.x_min / f.mean_x, f.a);
  for (double x : {0.004, 0.005, 0.01, 0.03, 0.1})
    EXPECT_NEAR(truncated_cdf(x, f), (phi_cdf(x / f.mean_x, f.a) - F0) / (1.0 - F0), 1e-12) << x;
  EXPECT_EQ(truncated_cdf(0.001, f), 0.0);
  EXPECT_NEAR(truncated_cdf(10.0, f), 1.0, 1e-12);
  // Its samples lie above the floor and follow it.
  const auto x = sample_truncated(5000, f, 3);
  EXPECT_GE(*std::min_element(x.begin(), x.end()), f.x_min);
  TruncatedShapeFit g = f;
  g.n = x.size();
  EXPECT_LT(truncated_ks_distance(x, g), 1.63 / std::sqrt(5000.0));
}

TEST(TruncatedShape, KsPValueTellsTheLawFromOtherShapes) {
  const auto x = areas(600, 1.2, 1e-3, 41);
  const double x_min = quantile(x, 0.35);
  const auto f = fit_truncated_shape(x, x_min);
  EXPECT_GT(truncated_ks_pvalue(f, truncated_ks_distance(x, f), 60, 5), 0.05);
  // Uniform areas above the same kind of floor: the cut law has a free scale as well as its
  // shape, so it takes more than a smooth change of shape to reject it (it absorbs a log-normal
  // of sigma 0.5 at this size), but not a sharp largest facet.
  std::vector<double> y;
  for (int i = 1; i <= 600; ++i) y.push_back(1e-3 * i / 600.0);
  const auto g = fit_truncated_shape(y, quantile(y, 0.35));
  // No resample is as far from its refit as these: p is the bootstrap's floor 1/(B+1).
  EXPECT_DOUBLE_EQ(truncated_ks_pvalue(g, truncated_ks_distance(y, g), 60, 5), 1.0 / 61.0);
}

TEST(TruncatedShape, RefusesTooFewAreasAndABadFloor) {
  const std::vector<double> x = {1, 2, 3, 4, 5, 6};
  EXPECT_THROW(fit_truncated_shape(x, 3.5), std::invalid_argument);
  EXPECT_THROW(fit_truncated_shape(x, 0.0), std::invalid_argument);
  EXPECT_NO_THROW(fit_truncated_shape(x, 1.0));
}
