// Regularized lower incomplete gamma function P(a, x) = gamma(a, x) / Gamma(a), needed for the
// CDF of the fragmentation-model distribution, F(xi; a) = P(a, sqrt(a(a+1) xi))
// (docs/STATISTICS.md §3.3). Series for x < a + 1, Lentz continued fraction for Q = 1 - P
// otherwise.
#pragma once

namespace crumple::analysis {

/// P(a, x) for a > 0, x >= 0; about 1e-14 relative accuracy. Throws on a <= 0 or x < 0.
double gamma_p(double a, double x);

}  // namespace crumple::analysis
