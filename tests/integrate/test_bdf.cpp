// Variable-step BDF (sim/integrate/bdf.hpp): exactness on polynomials with uneven steps, the
// error constant, and the measured convergence order with fixed steps on a nonlinear ODE.
#include "sim/integrate/bdf.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace crumple;

namespace {

std::vector<double> uneven_times(int count, unsigned seed) {
  // Newest first, steps between 0.3 and 1.7 (ratios up to about 5).
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.3, 1.7);
  std::vector<double> t{2.0};
  for (int i = 1; i < count; ++i) t.push_back(t.back() - 0.1 * U(rng));
  return t;
}

double poly(const std::vector<double>& a, double t) {
  double r = 0;
  for (std::size_t k = a.size(); k-- > 0;) r = r * t + a[k];
  return r;
}
double dpoly(const std::vector<double>& a, double t) {
  double r = 0;
  for (std::size_t k = a.size(); k-- > 1;) r = r * t + k * a[k];
  return r;
}

}  // namespace

TEST(Bdf, ConstantStepCoefficientsAreTheTextbookOnes) {
  // BDF2 with h = 1: x_{k+1} - 4/3 x_k + 1/3 x_{k-1} = 2/3 h v_{k+1}.
  auto c = bdf_coefficients({2.0, 1.0, 0.0});
  EXPECT_NEAR(c.alpha[0], -4.0 / 3, 1e-14);
  EXPECT_NEAR(c.alpha[1], 1.0 / 3, 1e-14);
  EXPECT_NEAR(c.beta, 2.0 / 3, 1e-14);
  // BDF4: beta = 12/25.
  c = bdf_coefficients({4.0, 3.0, 2.0, 1.0, 0.0});
  EXPECT_NEAR(c.beta, 12.0 / 25, 1e-14);
  EXPECT_NEAR(c.alpha[0], -48.0 / 25, 1e-13);
}

TEST(Bdf, VariableStepsReproducePolynomialsUpToTheOrder) {
  for (int s = 1; s <= 4; ++s)
    for (unsigned seed = 1; seed <= 5; ++seed) {
      const auto t = uneven_times(s + 2, seed);  // s+1 for the corrector, s+2 for the predictor
      const std::vector<double> tc(t.begin(), t.begin() + s + 1);
      const auto c = bdf_coefficients(tc);
      std::vector<double> a(s + 1);
      for (int k = 0; k <= s; ++k) a[k] = 0.7 - 0.4 * k + 0.1 * seed;  // degree s
      double r = poly(a, t[0]) - c.beta * c.h * dpoly(a, t[0]);
      for (int j = 1; j <= s; ++j) r += c.alpha[j - 1] * poly(a, t[j]);
      EXPECT_NEAR(r, 0.0, 1e-11) << "order " << s;
      // The predictor through t_1..t_{s+1} reproduces degree s exactly too.
      const std::vector<double> nodes(t.begin() + 1, t.end());
      const auto w = lagrange_weights(nodes, t[0]);
      double pred = 0;
      for (int j = 0; j <= s; ++j) pred += w[j] * poly(a, nodes[j]);
      EXPECT_NEAR(pred, poly(a, t[0]), 1e-11);
    }
}

TEST(Bdf, ErrorFactorIsExactForDegreeSPlusOne) {
  // For x = t^(s+1) the corrector (with the exact slope) and predictor errors are exactly
  // Cc D and Cp D, so x - x_corr = E (x_corr - x_pred) holds to rounding.
  for (int s = 1; s <= 4; ++s) {
    const auto t = uneven_times(s + 2, 10 + s);
    const auto c = bdf_coefficients(std::vector<double>(t.begin(), t.begin() + s + 1));
    auto x = [&](double tt) { return std::pow(tt, s + 1); };
    double xc = c.beta * c.h * (s + 1) * std::pow(t[0], s);
    for (int j = 1; j <= s; ++j) xc -= c.alpha[j - 1] * x(t[j]);
    const std::vector<double> nodes(t.begin() + 1, t.end());
    const auto w = lagrange_weights(nodes, t[0]);
    double xp = 0;
    for (int j = 0; j <= s; ++j) xp += w[j] * x(nodes[j]);
    const double E = bdf_error_factor(t);
    EXPECT_NEAR(x(t[0]) - xc, E * (xc - xp), 1e-10 * std::abs(x(t[0]) - xc) + 1e-13);
    EXPECT_NE(x(t[0]) - xc, 0.0);
  }
}

namespace {

// x' = -x^2, exact x = 1/(1+t): fixed steps, exact start-up
// values, scalar Newton for each implicit step. Returns the error at t = 2.
double bdf_global_error(int s, int n) {
  const double T = 2.0, h = T / n;
  auto exact = [](double t) { return 1.0 / (1.0 + t); };
  std::vector<double> xs;
  for (int k = 0; k < s; ++k) xs.push_back(exact(k * h));
  for (int k = s; k <= n; ++k) {
    std::vector<double> times{k * h};
    for (int j = 1; j <= s; ++j) times.push_back((k - j) * h);
    const auto c = bdf_coefficients(times);
    double hist = 0;
    for (int j = 1; j <= s; ++j) hist += c.alpha[j - 1] * xs[k - j];
    double x = xs[k - 1];
    for (int it = 0; it < 30; ++it) {  // r(x) = x + hist + beta h x^2
      const double r = x + hist + c.beta * h * x * x;
      x -= r / (1.0 + 2.0 * c.beta * h * x);
    }
    xs.push_back(x);
  }
  return std::abs(xs[n] - exact(T));
}

}  // namespace

TEST(Bdf, FixedStepConvergenceOrders) {
  for (int s = 1; s <= 4; ++s) {
    const double e1 = bdf_global_error(s, 40), e2 = bdf_global_error(s, 80);
    const double ratio = e1 / e2, expect = std::pow(2.0, s);
    std::printf("BDF%d: error %.3e -> %.3e, ratio %.2f (expect %.0f)\n", s, e1, e2, ratio, expect);
    if (s >= 3) {
      EXPECT_NEAR(ratio, expect, 0.15 * expect);
    } else {
      EXPECT_NEAR(ratio, expect, 0.25 * expect);
    }
  }
}

// The step-growth limits (bdf_growth_limit) keep variable-step BDF zero-stable: on a grid of
// constant ratio w the recurrence for x' = 0 has constant coefficients, and its extraneous
// roots (all but the root 1) stay within 0.9 at w = limit, while BDF4 at w = 2 (the error
// controller's own cap) has one of modulus about 2.8.
TEST(Bdf, GrowthLimitsKeepTheExtraneousRootsInsideTheUnitCircle) {
  const auto largest_extraneous = [](int s, double w) {
    std::vector<double> t{0.0};
    double h = 1.0;
    for (int j = 0; j < s; ++j, h /= w) t.push_back(t.back() - h);
    const BdfCoefficients c = bdf_coefficients(t);
    // Companion matrix of x_{k+1} = -sum_j alpha_j x_{k+1-j}.
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(s, s);
    for (int j = 0; j < s; ++j) C(0, j) = -c.alpha[j];
    for (int j = 1; j < s; ++j) C(j, j - 1) = 1.0;
    const Eigen::VectorXcd roots = C.eigenvalues();
    double big = 0, nearest_one = 1e9;
    int one = -1;
    for (int j = 0; j < s; ++j)
      if (std::abs(roots[j] - 1.0) < nearest_one) nearest_one = std::abs(roots[j] - 1.0), one = j;
    EXPECT_LT(nearest_one, 1e-6);  // consistency: the root 1
    for (int j = 0; j < s; ++j)
      if (j != one) big = std::max(big, std::abs(roots[j]));
    return big;
  };
  EXPECT_TRUE(std::isinf(bdf_growth_limit(1)));
  for (int s = 2; s <= 4; ++s) {
    const double w = bdf_growth_limit(s);
    EXPECT_LE(largest_extraneous(s, w), 0.9) << s;
    EXPECT_GT(largest_extraneous(s, w * 1.05), largest_extraneous(s, w)) << s;  // not slack
    EXPECT_LT(largest_extraneous(s, 1.0), largest_extraneous(s, w)) << s;
  }
  EXPECT_GT(largest_extraneous(4, 2.0), 2.5);
  EXPECT_GT(largest_extraneous(3, 2.0), 1.2);
  // The marginal ratios: 1 + sqrt(2), the golden ratio, 1.2807.
  EXPECT_NEAR(largest_extraneous(2, 1.0 + std::sqrt(2.0)), 1.0, 1e-6);
  EXPECT_NEAR(largest_extraneous(3, 0.5 * (1.0 + std::sqrt(5.0))), 1.0, 1e-6);
  EXPECT_NEAR(largest_extraneous(4, 1.2807), 1.0, 1e-3);
}
