// Regularized lower incomplete gamma function P(a, x) = gamma(a, x) / Gamma(a) and its complement
// Q = 1 - P, needed for the CDF of the fragmentation-model distribution, F(xi; a) =
// P(a, sqrt(a(a+1) xi)) (docs/STATISTICS.md §3.3), and for that law cut at a floor
// (fits/truncated_shape.hpp). Series for x < a + 1, Lentz continued fraction for Q otherwise.
#pragma once

namespace crumple::analysis {

/// P(a, x) for a > 0, x >= 0; about 1e-14 relative accuracy. Throws on a <= 0 or x < 0.
double gamma_p(double a, double x);

/// Q(a, x) = 1 - P(a, x), computed directly where it is small (x >= a + 1), so that its
/// logarithm stays accurate far in the tail (the truncated facet law divides by it). Same domain.
double gamma_q(double a, double x);

/// ln Q(a, x), finite where Q itself underflows (far in the tail, x of several hundred and
/// more). Same domain; -inf at x = inf.
double log_gamma_q(double a, double x);

}  // namespace crumple::analysis
