// One-dimensional minimisation shared by the fits: Brent's method in a bracket, and a scan of a
// whole range followed by Brent's method between the best scan point's neighbours, for
// objectives that may have more than one basin over the range (the log law's profile in ln n0,
// the truncated facet law's profiles in ln a and ln theta).
#pragma once

#include <algorithm>
#include <cmath>

namespace crumple::analysis {

/// Brent's minimisation of f on [a, b] (golden sections and parabolic steps; R. P. Brent,
/// Algorithms for Minimization without Derivatives, 1973, ch. 5) from the interior point x with
/// f(x) <= f(a), f(b); returns the minimiser, counts the iterations, and sets `converged` when
/// the bracket shrank to the tolerance before the iteration limit.
template <class F>
double brent_minimize(F f, double a, double b, double x, int& iterations, bool& converged) {
  constexpr double golden = 0.3819660112501051, eps = 1.4901161193847656e-08;  // sqrt(DBL_EPSILON)
  double w = x, v = x, fx = f(x), fw = fx, fv = fx, d = 0, e = 0;
  converged = false;
  for (iterations = 0; iterations < 200; ++iterations) {
    const double m = 0.5 * (a + b), tol = eps * std::abs(x) + 1e-12, t2 = 2 * tol;
    if (std::abs(x - m) <= t2 - 0.5 * (b - a)) {
      converged = true;
      break;
    }
    double p = 0, q = 0, r = 0;
    if (std::abs(e) > tol) {  // try a parabola through x, w, v
      r = (x - w) * (fx - fv);
      q = (x - v) * (fx - fw);
      p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) p = -p;
      q = std::abs(q);
      r = e, e = d;
    }
    if (std::abs(p) < std::abs(0.5 * q * r) && p > q * (a - x) && p < q * (b - x)) {
      d = p / q;
      const double u = x + d;
      if (u - a < t2 || b - u < t2) d = x < m ? tol : -tol;
    } else {
      e = (x < m ? b : a) - x;
      d = golden * e;
    }
    const double u = x + (std::abs(d) >= tol ? d : (d > 0 ? tol : -tol));
    const double fu = f(u);
    if (fu <= fx) {
      (u < x ? b : a) = x;
      v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw, w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  return x;
}

/// Minimiser of f over [lo, hi]: f at K + 1 evenly spaced points, then Brent's method between
/// the best point's neighbours; a minimum on an end of the range is returned there. Sets
/// `at_bound` when it is.
template <class F>
double scan_minimize(F f, double lo, double hi, int K, bool& at_bound) {
  const auto at = [&](int i) { return lo + i * (hi - lo) / K; };
  int best = 0;
  double best_f = f(lo);
  for (int i = 1; i <= K; ++i) {
    const double v = f(at(i));
    if (v < best_f) best_f = v, best = i;
  }
  int iterations = 0;
  bool converged = false;
  const double a = at(std::max(best - 1, 0)), b = at(std::min(best + 1, K));
  const double start = best == 0 || best == K ? 0.5 * (a + b) : at(best);
  double x = brent_minimize(f, a, b, start, iterations, converged);
  if (best_f < f(x)) x = at(best);  // the scan point itself was the lowest (a minimum on a bound)
  // On an end, or closer to it than Brent's tolerance could resolve.
  const double tol = 1e-9 * (hi - lo);
  at_bound = x - lo <= tol || hi - x <= tol;
  return x;
}

}  // namespace crumple::analysis
