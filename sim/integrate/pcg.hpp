// Preconditioned conjugate gradient that watches for the signs of a matrix that is not SPD.
//
// Eigen's ConjugateGradient does not expose the curvature p^T A p of its search directions, so
// the integrator runs this loop (the same algorithm, the same |r| / |b| stopping rule) with any
// preconditioner that has Eigen's solve() interface. It stops with `indefinite` as soon as
// p^T A p <= 0 (negative curvature: A is not positive definite) or r^T M^{-1} r <= 0 (the
// preconditioner is not positive definite), or when a value is not finite.
#pragma once

#include "sim/core/types.hpp"

#include <cmath>

namespace crumple {

struct CgResult {
  bool converged = false;
  bool indefinite = false;  ///< p^T A p <= 0, r^T z <= 0 or NaN met
  int iterations = 0;
  double rel_residual = 0;
};

/// z = M^{-1} r, through M.apply(r, z) where the preconditioner has it (no allocation per
/// iteration), else through Eigen's M.solve(r).
template <class Precond>
void apply_preconditioner(const Precond& M, const VecX& r, VecX& z) {
  if constexpr (requires { M.apply(r, z); })
    M.apply(r, z);
  else
    z = M.solve(r);
}

/// Solves A x = b from x = 0. tol is the relative residual |b - A x| / |b|.
template <class Precond>
CgResult pcg_solve(const SpMat& A, const VecX& b, VecX& x, const Precond& M, double tol,
                   int max_iters) {
  CgResult res;
  x.setZero(b.size());
  const double bnorm = b.norm();
  if (!std::isfinite(bnorm)) {
    res.indefinite = true;
    return res;
  }
  if (bnorm == 0.0) {
    res.converged = true;
    return res;
  }
  VecX r = b, z;
  apply_preconditioner(M, r, z);
  VecX p = z, Ap(b.size());
  double rz = r.dot(z);
  if (!(rz > 0.0)) {
    res.indefinite = true;
    return res;
  }
  for (int it = 1; it <= max_iters; ++it) {
    Ap.noalias() = A * p;
    const double pAp = p.dot(Ap);
    res.iterations = it;
    if (!(pAp > 0.0)) {  // also false for NaN
      res.indefinite = true;
      return res;
    }
    const double alpha = rz / pAp;
    x += alpha * p;
    r -= alpha * Ap;
    res.rel_residual = r.norm() / bnorm;
    if (res.rel_residual <= tol) {
      res.converged = true;
      return res;
    }
    apply_preconditioner(M, r, z);
    const double rz_new = r.dot(z);
    if (!(rz_new > 0.0)) {
      res.indefinite = true;
      return res;
    }
    p = z + (rz_new / rz) * p;
    rz = rz_new;
  }
  return res;
}

/// M = I, with the solve() interface pcg_solve needs.
struct IdentityPrecond {
  const VecX& solve(const VecX& r) const { return r; }
};

}  // namespace crumple
