// Tests of gamma_p (analysis/fits/incomplete_gamma.hpp) against closed forms and independent
// reference values (scipy.special.gammainc).
#include "analysis/fits/incomplete_gamma.hpp"

#include <gtest/gtest.h>

#include <cmath>

using crumple::analysis::gamma_p;

TEST(IncompleteGamma, ClosedForms) {
  for (double x : {1e-4, 0.1, 0.7, 1.0, 2.5, 6.0, 30.0}) {
    EXPECT_NEAR(gamma_p(1.0, x), 1.0 - std::exp(-x), 1e-13) << x;
    EXPECT_NEAR(gamma_p(0.5, x), std::erf(std::sqrt(x)), 1e-13) << x;
    EXPECT_NEAR(gamma_p(3.0, x), 1.0 - std::exp(-x) * (1.0 + x + 0.5 * x * x), 1e-13) << x;
  }
}

TEST(IncompleteGamma, ReferenceValues) {
  struct Case { double a, x, p; };
  for (const Case& c : {Case{0.3, 5.0, 0.9993486812492816}, Case{10, 3, 0.0011024881301154815},
                        Case{50, 60, 0.9155933189063082}, Case{2.5, 0.1, 0.0008861387888124438},
                        Case{0.05, 0.01, 0.8155598057412847}, Case{7.5, 7.5, 0.5485827887742752},
                        Case{200, 190, 0.2433474271006237}})
    EXPECT_NEAR(gamma_p(c.a, c.x), c.p, 1e-11 * std::max(1.0, c.p)) << c.a << " " << c.x;
}

TEST(IncompleteGamma, LimitsAndDomain) {
  EXPECT_EQ(gamma_p(2.0, 0.0), 0.0);
  EXPECT_NEAR(gamma_p(2.0, 1e3), 1.0, 1e-15);
  EXPECT_THROW(gamma_p(0.0, 1.0), std::domain_error);
  EXPECT_THROW(gamma_p(1.0, -1.0), std::domain_error);
}

TEST(IncompleteGamma, ComplementAccurateInTheTail) {
  using crumple::analysis::gamma_q;
  for (double x : {1e-4, 0.1, 0.7, 2.5, 6.0, 30.0}) {
    EXPECT_NEAR(gamma_q(2.0, x) + gamma_p(2.0, x), 1.0, 1e-14) << x;
    EXPECT_NEAR(gamma_q(0.5, x), std::erfc(std::sqrt(x)), 1e-13 * std::max(1.0, std::erfc(std::sqrt(x)))) << x;
  }
  // Where 1 - P has lost every digit, Q keeps its relative accuracy.
  for (double x : {40.0, 80.0, 300.0}) {
    EXPECT_NEAR(gamma_q(1.0, x) / std::exp(-x), 1.0, 1e-12) << x;
    EXPECT_NEAR(gamma_q(3.0, x) / (std::exp(-x) * (1.0 + x + 0.5 * x * x)), 1.0, 1e-12) << x;
  }
  EXPECT_EQ(gamma_q(2.0, 0.0), 1.0);
  EXPECT_THROW(gamma_q(-1.0, 1.0), std::domain_error);
}

TEST(IncompleteGamma, LogComplementWhereQUnderflows) {
  using crumple::analysis::gamma_q;
  using crumple::analysis::log_gamma_q;
  for (double x : {1e-3, 0.5, 3.0, 40.0})
    EXPECT_NEAR(log_gamma_q(2.5, x), std::log(gamma_q(2.5, x)), 1e-12) << x;
  // Q(1, x) = e^-x and Q(3, x) = e^-x (1 + x + x^2/2): their logs far past underflow of Q.
  for (double x : {800.0, 5000.0}) {
    EXPECT_EQ(gamma_q(1.0, x), 0.0);
    EXPECT_NEAR(log_gamma_q(1.0, x), -x, 1e-9 * x) << x;
    EXPECT_NEAR(log_gamma_q(3.0, x), -x + std::log(1.0 + x + 0.5 * x * x), 1e-9 * x) << x;
  }
  EXPECT_EQ(log_gamma_q(2.0, 0.0), 0.0);
}
