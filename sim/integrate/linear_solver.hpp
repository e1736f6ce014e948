// The linear solve of the reduced Newton system A dx = b (paper eq. 35, §3.3), with the solver
// chosen by IntegratorSettings::linear_solver: CG with block-Jacobi, two-level (block Jacobi +
// patch rigid motions), plain or incomplete-Cholesky preconditioning (pcg.hpp, which detects
// negative curvature), or a direct sparse LDL^T (SPD when every pivot of D is positive). A
// matrix found not SPD, a CG that does not converge, or a non-finite value is reported in the
// result; the integrator rejects the step.
#pragma once

#include "sim/integrate/block_jacobi.hpp"
#include "sim/integrate/settings.hpp"
#include "sim/integrate/two_level.hpp"

#include <string>

namespace crumple {

struct LinearSolveResult {
  bool ok = false;
  bool not_spd = false;  ///< the matrix (or its preconditioner) was found not SPD
  int iterations = 0;    ///< CG iterations (0 for the direct solver)
  std::string failure;   ///< reason when !ok
};

class LinearSolver {
 public:
  LinearSolver(LinearSolverKind kind, int block_size, double tol, int max_iters,
               int coarse_nodes = 32);
  /// Solves A x = b, A symmetric (both triangles stored), on the pattern's sparsity, CG to
  /// the relative residual given at construction. `positions` (3n, the nodes' current
  /// positions) span the two_level coarse space and are required for it.
  LinearSolveResult solve(const SpMat& A, const VecX& b, VecX& x,
                          const VecX* positions = nullptr) {
    return solve(A, b, x, tol_, positions);
  }
  /// The same with CG stopping at relative residual `tol` (an inexact Newton step, forcing.hpp).
  LinearSolveResult solve(const SpMat& A, const VecX& b, VecX& x, double tol,
                          const VecX* positions = nullptr);
  LinearSolverKind kind() const { return kind_; }

 private:
  LinearSolverKind kind_;
  double tol_;
  int max_iters_;
  BlockJacobiPreconditioner block_jacobi_;
  TwoLevelPreconditioner two_level_;
};

}  // namespace crumple
