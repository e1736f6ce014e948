// Linear solvers of the reduced Newton system (linear_solver.hpp).
#include "sim/integrate/linear_solver.hpp"

#include "sim/integrate/pcg.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>

#include <stdexcept>

namespace crumple {

LinearSolver::LinearSolver(LinearSolverKind kind, int block_size, double tol, int max_iters,
                           int coarse_nodes)
    : kind_(kind),
      tol_(tol),
      max_iters_(max_iters),
      block_jacobi_(block_size),
      two_level_(block_size, coarse_nodes) {}

namespace {

LinearSolveResult from_cg(const CgResult& cg) {
  LinearSolveResult r;
  r.iterations = cg.iterations;
  r.ok = cg.converged;
  r.not_spd = cg.indefinite;
  if (cg.indefinite)
    r.failure = "matrix not SPD (CG met non-positive curvature)";
  else if (!cg.converged)
    r.failure = "CG did not converge (relative residual " + std::to_string(cg.rel_residual) + ")";
  return r;
}

}  // namespace

LinearSolveResult LinearSolver::solve(const SpMat& A, const VecX& b, VecX& x, double tol,
                                     const VecX* positions) {
  switch (kind_) {
    case LinearSolverKind::TwoLevelCG: {
      if (!positions || positions->size() != A.rows())
        throw std::logic_error("LinearSolver: two_level needs the node positions");
      two_level_.compute(A, *positions);
      if (two_level_.info() != Eigen::Success) {
        LinearSolveResult r;
        r.not_spd = true;
        r.failure = "matrix not SPD (" + two_level_.failure() + ")";
        return r;
      }
      return from_cg(pcg_solve(A, b, x, two_level_, tol, max_iters_));
    }
    case LinearSolverKind::BlockJacobiCG: {
      block_jacobi_.compute(A);
      if (block_jacobi_.info() != Eigen::Success) {
        LinearSolveResult r;
        r.not_spd = true;
        r.failure = "matrix not SPD (Cholesky of diagonal block " +
                    std::to_string(block_jacobi_.failed_block()) + " failed)";
        return r;
      }
      return from_cg(pcg_solve(A, b, x, block_jacobi_, tol, max_iters_));
    }
    case LinearSolverKind::PlainCG:
      return from_cg(pcg_solve(A, b, x, IdentityPrecond{}, tol, max_iters_));
    case LinearSolverKind::IncompleteCholeskyCG: {
      const SpMatCol Ac(A);
      Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>> ic(Ac);
      if (ic.info() != Eigen::Success) {
        LinearSolveResult r;
        r.not_spd = true;
        r.failure = "incomplete Cholesky failed";
        return r;
      }
      struct Wrap {
        const decltype(ic)& m;
        VecX solve(const VecX& r) const { return m.solve(r); }
      };
      return from_cg(pcg_solve(A, b, x, Wrap{ic}, tol, max_iters_));
    }
    case LinearSolverKind::DirectLDLT: {
      LinearSolveResult r;
      const SpMatCol Ac(A);
      Eigen::SimplicialLDLT<SpMatCol> ldlt(Ac);
      if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0.0)) {
        r.not_spd = true;
        r.failure = "matrix not SPD (LDL^T pivot <= 0)";
        return r;
      }
      x = ldlt.solve(b);
      r.ok = x.allFinite();
      if (!r.ok) r.failure = "non-finite solution of the direct solve";
      return r;
    }
  }
  return {};
}

}  // namespace crumple
