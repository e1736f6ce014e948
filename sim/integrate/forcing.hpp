// Forcing terms of the inexact Newton iteration of the quasistatic step: the relative residual
// |b - A dx| / |b| to which CG solves the reduced system (eq. 35) at Newton iteration k.
//
// Newton stops when its update is small (|dx_k| <= newton_tol in the error-weighted RMS norm of
// error_norm.hpp), so the linear solve only has to be as accurate as that test can see. The
// first iteration carries the whole predictor error (|dx_1| of order 1 in that norm when the
// step size is set by the error test) and is solved to cg_tol. After it, the linear error of
// the coming update, about eta_k |dx_k|, must stay below the convergence tolerance or it alone
// forces one more iteration; with |dx_k| estimated by the update just taken (Newton contracts):
//     eta_1 = cg_tol,   eta_k = clamp(0.5 newton_tol / |dx_{k-1}|, cg_tol, cg_tol_max).
// A Newton iteration close to convergence is thus solved loosely, a slow one tightly.
// (Eisenstat and Walker's residual-ratio rule, tried first, loosens the first solve and tightens
// the second: the wrong way round for an update-based test where two iterations are the norm;
// it cost 1.7 times more linear-solve time per Newton iteration on the radial benchmark.)
#pragma once

#include <algorithm>
#include <cmath>

namespace crumple {

struct ForcingTerms {
  double eta_min = 1e-2;     ///< cg_tol: the first iteration and the tightest solve
  double eta_max = 1e-1;     ///< cg_tol_max: the loosest (eta_min == eta_max: a fixed tolerance)
  double newton_tol = 0.1;   ///< the Newton update test, weighted RMS

  /// Tolerance of Newton iteration k (1-based); prev_update = |dx_{k-1}| (weighted RMS).
  double at(int k, double prev_update) const {
    if (k <= 1 || !(prev_update > 0) || !std::isfinite(prev_update)) return eta_min;
    return std::clamp(0.5 * newton_tol / prev_update, eta_min, eta_max);
  }
};

}  // namespace crumple
