// Fits: the log law (cumulative and on increments) recovers known (C, n0) within its reported
// uncertainty; the facet-shape estimators recover a known a from samples of phi; the universal
// a; the log-binned density; the collapse over several compaction ratios.
#include "analysis/facets/area_distribution.hpp"
#include "analysis/fits/facet_shape.hpp"
#include "analysis/fits/log_law.hpp"
#include "analysis/fits/shape_bootstrap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace crumple::analysis;

TEST(LogLaw, ExactDataRecovered) {
  std::vector<double> n, l;
  for (int i = 1; i <= 6; ++i) n.push_back(i), l.push_back(14.0 * std::log(1.0 + i / 2.7));
  const LogLawFit f = fit_log_law(n, l);
  EXPECT_TRUE(f.converged);
  EXPECT_NEAR(f.C, 14.0, 1e-6);
  EXPECT_NEAR(f.n0, 2.7, 1e-6);
  EXPECT_NEAR(f.r2, 1.0, 1e-12);
  EXPECT_FALSE(f.at_bound);
}

// Data whose least-squares optimum lies at no finite n0 stop on the bound of the search: all the
// length in the first cycle (n0 -> 0) or no bend at all (n0 -> oo). C is then the best C at that
// n0 (the law is linear in C), and the covariance still says that n0 is not determined.
TEST(LogLaw, OptimumBeyondTheRangeStopsOnItsBound) {
  const std::vector<double> n = {1, 2, 3, 4, 5};
  auto best_C = [&](const std::vector<double>& y, const std::vector<double>& s, double n0) {
    double gy = 0, gg = 0;
    for (std::size_t i = 0; i < n.size(); ++i) {
      const double g = std::log1p(n[i] / n0), w = 1 / (s[i] * s[i]);
      gy += w * g * y[i], gg += w * g * g;
    }
    return gy / gg;
  };
  const std::vector<double> flat = {10.0, 10.1, 10.05, 10.2, 10.1}, s = {0.3, 0.2, 0.2, 0.3, 0.2};
  const LogLawFit f = fit_log_law(n, flat, s);
  EXPECT_TRUE(f.at_bound);
  EXPECT_TRUE(f.converged);
  EXPECT_NEAR(f.n0, kN0Min, 1e-9 * kN0Min);
  EXPECT_NEAR(f.C, best_C(flat, s, kN0Min), 1e-9 * f.C);
  EXPECT_GT(f.sigma_n0, f.n0);
  const std::vector<double> line = {2.0, 4.1, 5.9, 8.0, 10.1}, ones(5, 1.0);
  const LogLawFit g = fit_log_law(n, line);
  EXPECT_TRUE(g.at_bound);
  EXPECT_NEAR(g.n0, kN0Max, 1e-9 * kN0Max);
  EXPECT_NEAR(g.C, best_C(line, ones, kN0Max), 1e-9 * g.C);
  EXPECT_NEAR(g.C / g.n0, 2.0, 0.05);  // the slope is what such data fix
  // Falling data: the best C >= 0 is 0, on its bound.
  const LogLawFit h = fit_log_law_increments({0, 1, 2, 3}, {1, 2, 3, 4}, {0.5, -1.0, -1.5, -2.0});
  EXPECT_TRUE(h.at_bound);
  EXPECT_GE(h.C, 0.0);
}

TEST(LogLaw, IncrementFitRecoversExactIncrements) {
  // dl_n = C [ln(1 + n/n0) - ln(1 + (n-1)/n0)] for n = 1..5, and with a gap (cycle 3 missing).
  auto cum = [](double n) { return 14.0 * std::log(1.0 + n / 2.7); };
  std::vector<double> from, to, dl;
  for (int i = 1; i <= 5; ++i)
    from.push_back(i - 1), to.push_back(i), dl.push_back(cum(i) - cum(i - 1));
  const LogLawFit f = fit_log_law_increments(from, to, dl);
  EXPECT_TRUE(f.converged);
  EXPECT_NEAR(f.C, 14.0, 1e-6);
  EXPECT_NEAR(f.n0, 2.7, 1e-6);
  EXPECT_NEAR(f.rss, 0.0, 1e-16);
  EXPECT_EQ(f.dof, 3);
  EXPECT_NE(f.model.find("increments"), std::string::npos);
  const LogLawFit g =
      fit_log_law_increments({0, 1, 2, 4}, {1, 2, 4, 6},
                             {cum(1), cum(2) - cum(1), cum(4) - cum(2), cum(6) - cum(4)});
  EXPECT_NEAR(g.C, 14.0, 1e-6);
  EXPECT_NEAR(g.n0, 2.7, 1e-6);
  EXPECT_THROW(fit_log_law_increments({0, 1}, {1, 2}, {1, 1}), std::invalid_argument);
  EXPECT_THROW(fit_log_law_increments({0, 2, 2}, {1, 2, 3}, {1, 1, 1}), std::invalid_argument);
}

TEST(LogLaw, IncrementFitUncertaintyCoversTruth) {
  // Independent noise on each cycle's increment (the new creases of one crumple): the increment
  // fit's 1-sigma intervals cover the truth about as often as they should, where the cumulative
  // fit to the running sums (correlated residuals) covers it less often.
  const double C = 30.0, n0 = 2.5, noise = 0.6;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> N(0.0, noise);
  int inc_C = 0, cum_C = 0;
  const int R = 300;
  for (int r = 0; r < R; ++r) {
    std::vector<double> n, from, l, dl;
    double sum = 0;
    for (int i = 1; i <= 10; ++i) {
      const double d = C * (std::log(1.0 + i / n0) - std::log(1.0 + (i - 1) / n0)) + N(rng);
      sum += d;
      n.push_back(i), from.push_back(i - 1), dl.push_back(d), l.push_back(sum);
    }
    const LogLawFit fi = fit_log_law_increments(from, n, dl);
    const LogLawFit fc = fit_log_law(n, l);
    inc_C += std::abs(fi.C - C) < fi.sigma_C;
    cum_C += std::abs(fc.C - C) < fc.sigma_C;
  }
  std::printf("1-sigma coverage of C with random-walk data: increment fit %.2f, cumulative %.2f\n",
              inc_C / double(R), cum_C / double(R));
  EXPECT_GE(inc_C, 0.6 * R);
  EXPECT_LT(cum_C, inc_C);
}

TEST(LogLaw, UncertaintyCoversTruth) {
  const double C = 30.0, n0 = 2.5, noise = 0.6;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> N(0.0, noise);
  int in1_C = 0, in1_n0 = 0, in3 = 0;
  const int R = 300;
  for (int r = 0; r < R; ++r) {
    std::vector<double> n, l;
    for (int i = 1; i <= 10; ++i) n.push_back(i), l.push_back(C * std::log(1.0 + i / n0) + N(rng));
    const LogLawFit f = fit_log_law(n, l);
    in1_C += std::abs(f.C - C) < f.sigma_C;
    in1_n0 += std::abs(f.n0 - n0) < f.sigma_n0;
    in3 += std::abs(f.C - C) < 3 * f.sigma_C && std::abs(f.n0 - n0) < 3 * f.sigma_n0;
  }
  // Nominal 1-sigma coverage is 68 %; with 8 degrees of freedom the estimated sigma scatters,
  // so a little less is expected.
  std::printf("log-law coverage over %d noisy realisations: 1-sigma C %.2f, n0 %.2f; 3-sigma both %.2f\n",
              R, in1_C / double(R), in1_n0 / double(R), in3 / double(R));
  EXPECT_GE(in1_C, 0.6 * R);
  EXPECT_GE(in1_n0, 0.6 * R);
  EXPECT_GE(in3, 0.95 * R);
}

TEST(LogLaw, WeightedChi2AndConversion) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> N(0.0, 1.0);
  std::vector<double> n, l, s;
  for (int i = 1; i <= 24; ++i) {
    const double sig = 0.2 + 0.05 * i;
    n.push_back(i), s.push_back(sig), l.push_back(52 * 0.73 * std::log(1 + 0.1 * i / 0.27) + sig * N(rng));
  }
  const LogLawFit f = fit_log_law(n, l, s);
  EXPECT_TRUE(f.weighted);
  EXPECT_NEAR(f.chi2_red, 1.0, 0.6);  // chi^2/22 has standard deviation 0.3
  const auto k = to_experiment_constants(f, 0.27);
  EXPECT_NEAR(k.c1, 52.0, 4 * k.sigma_c1);
  EXPECT_NEAR(k.c2, 0.1, 4 * k.sigma_c2);
  EXPECT_THROW(fit_log_law({1, 2}, {1, 2}), std::invalid_argument);
}

// The collapse: the experiments' law over seven compaction ratios at once. Exact increments
// give back (c1, c2); noisy ones are covered by the reported 1-sigma errors about as often as
// they should be; a single compaction agrees with the one-compaction fit converted by
// to_experiment_constants.
namespace {
const std::vector<double> kExperimentD = {0.63, 0.45, 0.36, 0.27, 0.18, 0.09, 0.045};
double law(double c1, double c2, double D, double n) {
  return c1 * (1 - D) * std::log(1 + c2 * n / D);
}
}  // namespace

TEST(Collapse, ExactIncrementsRecovered) {
  std::vector<double> D, from, to, dl;
  for (double d : kExperimentD)
    for (int n = 1; n <= 10; ++n)
      D.push_back(d), from.push_back(n - 1), to.push_back(n),
          dl.push_back(law(52, 0.1, d, n) - law(52, 0.1, d, n - 1));
  const CollapseFit f = fit_collapse(D, from, to, dl);
  EXPECT_TRUE(f.converged);
  EXPECT_FALSE(f.at_bound);
  EXPECT_NEAR(f.c1, 52.0, 1e-6);
  EXPECT_NEAR(f.c2, 0.1, 1e-9);
  EXPECT_EQ(f.points, 70);
  EXPECT_EQ(f.dof, 68);
  EXPECT_NEAR(f.chi2, 0.0, 1e-12);
  EXPECT_THROW(fit_collapse({0.3, 1.0, 0.3}, {0, 1, 2}, {1, 2, 3}, {1, 1, 1}),
               std::invalid_argument);  // D = 1: no compaction
  EXPECT_THROW(fit_collapse({0.3, 0.3}, {0, 1}, {1, 2}, {1, 1}), std::invalid_argument);
}

TEST(Collapse, UncertaintyCoversTruthAndOneCompactionAgrees) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> N(0.0, 1.0);
  const int R = 300;
  int in_c1 = 0, in_c2 = 0;
  for (int r = 0; r < R; ++r) {
    std::vector<double> D, from, to, dl, s;
    for (double d : kExperimentD)
      for (int n = 1; n <= 10; ++n) {
        const double sig = 0.5 + 0.1 * n;
        D.push_back(d), from.push_back(n - 1), to.push_back(n), s.push_back(sig);
        dl.push_back(law(52, 0.1, d, n) - law(52, 0.1, d, n - 1) + sig * N(rng));
      }
    const CollapseFit f = fit_collapse(D, from, to, dl, s);
    in_c1 += std::abs(f.c1 - 52) < f.sigma_c1;
    in_c2 += std::abs(f.c2 - 0.1) < f.sigma_c2;
  }
  std::printf("collapse coverage over %d realisations: 1-sigma c1 %.2f, c2 %.2f\n", R,
              in_c1 / double(R), in_c2 / double(R));
  EXPECT_GE(in_c1, 0.6 * R);
  EXPECT_GE(in_c2, 0.6 * R);
  EXPECT_LE(in_c1, 0.76 * R);  // errors not inflated either
  EXPECT_LE(in_c2, 0.76 * R);

  // One compaction: the same numbers as the single-compaction fit and its conversion.
  std::vector<double> D, from, to, dl, s;
  for (int n = 1; n <= 8; ++n) {
    D.push_back(0.27), from.push_back(n - 1), to.push_back(n), s.push_back(0.4);
    dl.push_back(law(40, 0.2, 0.27, n) - law(40, 0.2, 0.27, n - 1) + 0.4 * N(rng));
  }
  const CollapseFit c = fit_collapse(D, from, to, dl, s);
  const ExperimentConstants k =
      to_experiment_constants(fit_log_law_increments(from, to, dl, s), 0.27);
  EXPECT_NEAR(c.c1, k.c1, 1e-6 * k.c1);
  EXPECT_NEAR(c.c2, k.c2, 1e-6 * k.c2);
  EXPECT_NEAR(c.sigma_c1, k.sigma_c1, 1e-5 * k.sigma_c1);
  EXPECT_NEAR(c.sigma_c2, k.sigma_c2, 1e-5 * k.sigma_c2);
}

TEST(FacetShape, DensityAndCdfConsistent) {
  for (double a : {0.4, 1.0, 2.5}) {
    // integrate phi on a log grid and compare with F; also check <xi> = 1
    double F = 0, mean = 0;
    const double lo = std::log(1e-10), hi = std::log(1e4);  // the stretched-exponential tail is long at small a
    const int M = 20000;
    for (int i = 0; i < M; ++i) {
      const double u = lo + (i + 0.5) * (hi - lo) / M, xi = std::exp(u);
      const double w = phi_density(xi, a) * xi * (hi - lo) / M;
      F += w;
      mean += w * xi;
    }
    EXPECT_NEAR(F + phi_cdf(1e-10, a), phi_cdf(1e4, a), 2e-4) << a;
    EXPECT_NEAR(mean, 1.0, 2e-3) << a;
  }
}

TEST(FacetShape, RecoversKnownA) {
  for (double a : {0.6, 1.5}) {
    const auto xi = scaled_areas(sample_phi(4000, a, 11));
    const double fit = fit_a_mle(xi);
    std::printf("a = %.2f: a_fit %.4f, a_moment %.4f (4000 samples)\n", a, fit, a_moment(xi));
    EXPECT_NEAR(fit / a, 1.0, 0.06) << a;
    EXPECT_NEAR(a_moment(xi) / a, 1.0, 0.2) << a;
    const Interval iv = bootstrap_a_interval(xi, 60, 5);
    EXPECT_LT(iv.lo, a);
    EXPECT_GT(iv.hi, a);
    const double d = ks_distance(xi, fit);
    EXPECT_LT(d, 1.63 / std::sqrt(4000.0));  // 1 % critical value, conservative for a fitted a
    EXPECT_GT(ks_distance(xi, 3.0 * a), 3.0 * d);
  }
}

TEST(FacetShape, KsPValueDistinguishesModels) {
  const auto good = scaled_areas(sample_phi(300, 1.0, 21));
  const double pg = ks_pvalue_parametric(300, fit_a_mle(good), ks_distance(good, fit_a_mle(good)), 100, 9);
  EXPECT_GT(pg, 0.01);
  // Uniform areas are not phi-distributed at any a.
  std::vector<double> u;
  for (int i = 1; i <= 300; ++i) u.push_back(i / 300.0);
  const auto xi = scaled_areas(u);
  const double a = fit_a_mle(xi);
  EXPECT_LT(ks_pvalue_parametric(300, a, ks_distance(xi, a), 100, 9), 0.02);
}

TEST(FacetShape, UniversalCurve) {
  // docs/STATISTICS.md §6.4: a = 1 at s = 2/tau^2; a = 2 at s = 3/(8 tau^2).
  EXPECT_NEAR(a_universal(2.0 / (kTau * kTau)), 1.0, 1e-9);
  EXPECT_NEAR(a_universal(3.0 / (8.0 * kTau * kTau)), 2.0, 1e-9);
  EXPECT_LT(a_universal(1e-2), a_universal(1e-3));  // more facets, larger a
}

TEST(AreaDistribution, NormalisedLogBins) {
  const auto xi = scaled_areas(sample_phi(2000, 0.8, 4));
  const auto bins = log_binned_density(xi);
  double total = 0;
  long count = 0;
  for (const auto& b : bins) {
    EXPECT_NEAR(b.hi / b.lo, kAreaBinRatio, 1e-12);
    total += b.density * (b.hi - b.lo);
    count += b.count;
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
  EXPECT_EQ(count, 2000);
  EXPECT_LE(bins.front().lo, *std::min_element(xi.begin(), xi.end()));
  EXPECT_GT(bins.back().hi, *std::max_element(xi.begin(), xi.end()));
}
