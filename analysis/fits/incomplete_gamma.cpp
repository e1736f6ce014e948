// Regularized incomplete gamma; see incomplete_gamma.hpp.
#include "analysis/fits/incomplete_gamma.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace crumple::analysis {
namespace {

constexpr double kEps = 1e-15;
constexpr int kMaxIter = 10000;

// x^a e^{-x} / Gamma(a) in logs, the common prefactor of both expansions.
double log_prefactor(double a, double x) { return a * std::log(x) - x - std::lgamma(a); }

// P(a,x) = prefactor * sum_k x^k / (a (a+1) ... (a+k)); converges fast for x < a + 1.
double series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int k = 1; k < kMaxIter; ++k) {
    term *= x / (a + k);
    sum += term;
    if (std::abs(term) < std::abs(sum) * kEps) break;
  }
  return sum * std::exp(log_prefactor(a, x));
}

// Q(a,x) = prefactor * h, h = 1/(x+1-a- 1(1-a)/(x+3-a- 2(2-a)/(x+5-a- ...))), modified Lentz;
// returns h.
double continued_fraction_h(double a, double x) {
  const double tiny = std::numeric_limits<double>::min() / kEps;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < kMaxIter; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < kEps) break;
  }
  return h;
}

double continued_fraction(double a, double x) {
  return std::exp(log_prefactor(a, x)) * continued_fraction_h(a, x);
}

}  // namespace

double gamma_p(double a, double x) {
  if (!(a > 0) || !(x >= 0)) throw std::domain_error("gamma_p: need a > 0 and x >= 0");
  if (x == 0) return 0.0;
  if (std::isinf(x)) return 1.0;
  return x < a + 1.0 ? series(a, x) : 1.0 - continued_fraction(a, x);
}

double gamma_q(double a, double x) {
  if (!(a > 0) || !(x >= 0)) throw std::domain_error("gamma_q: need a > 0 and x >= 0");
  if (x == 0) return 1.0;
  if (std::isinf(x)) return 0.0;
  return x < a + 1.0 ? 1.0 - series(a, x) : continued_fraction(a, x);
}

double log_gamma_q(double a, double x) {
  if (!(a > 0) || !(x >= 0)) throw std::domain_error("log_gamma_q: need a > 0 and x >= 0");
  if (x == 0) return 0.0;
  if (std::isinf(x)) return -std::numeric_limits<double>::infinity();
  return x < a + 1.0 ? std::log1p(-series(a, x))
                     : log_prefactor(a, x) + std::log(continued_fraction_h(a, x));
}

}  // namespace crumple::analysis
