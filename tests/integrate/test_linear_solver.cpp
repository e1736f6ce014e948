// Linear solvers of the reduced system (sim/integrate/linear_solver.hpp, block_jacobi.hpp):
// all agree on an SPD sheet matrix, block-Jacobi cuts CG iterations, the preconditioner works
// inside Eigen's ConjugateGradient, and an indefinite matrix is reported as not SPD.
#include "sim/integrate/linear_solver.hpp"
#include "sim/integrate/pcg.hpp"
#include "sim/model/sheet_model.hpp"
#include "tests/support/grid_mesh.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <gtest/gtest.h>

using namespace crumple;

namespace {

// Hx + Hv / (beta h) of a crumpled 10 x 10 sheet: the matrix the integrator solves.
SpMat sheet_matrix(double shift) {
  static const Mesh mesh = crumple::testing::grid_mesh(10, 10, 1.0, 1.0, 0.15, 5);
  ModelParams mp;
  mp.ks = 100;
  mp.kb = 0.05;
  mp.b_iso = 1.0;
  SheetModel model(mesh, mp);
  State s = model.rest_state();
  for (Index i = 0; i < mesh.num_nodes(); ++i)
    s.x[3 * i + 2] = 0.05 * std::sin(7 * s.x[3 * i]) * std::cos(5 * s.x[3 * i + 1]);
  Jacobians J;
  model.jacobians(s, J, false);
  SpMat A = J.Hx + shift * J.Hv;
  return A;
}

}  // namespace

TEST(LinearSolver, AllSolversAgreeAndBlockJacobiHelps) {
  const SpMat A = sheet_matrix(10.0);
  const VecX b = VecX::Random(A.rows());  // random rhs: a vector of ones hides differences
  VecX ref;
  LinearSolver direct(LinearSolverKind::DirectLDLT, 18, 1e-10, 5000);
  ASSERT_TRUE(direct.solve(A, b, ref).ok);
  int its[3];
  const LinearSolverKind kinds[3] = {LinearSolverKind::PlainCG, LinearSolverKind::BlockJacobiCG,
                                     LinearSolverKind::IncompleteCholeskyCG};
  for (int k = 0; k < 3; ++k) {
    LinearSolver ls(kinds[k], 18, 1e-10, 5000);
    VecX x;
    const auto r = ls.solve(A, b, x);
    ASSERT_TRUE(r.ok) << to_string(kinds[k]) << ": " << r.failure;
    EXPECT_LT((x - ref).norm() / ref.norm(), 1e-7) << to_string(kinds[k]);
    its[k] = r.iterations;
  }
  std::printf("CG iterations: plain %d, block Jacobi(18) %d, incomplete Cholesky %d\n", its[0],
              its[1], its[2]);
  EXPECT_LT(its[1], its[0]);
}

TEST(LinearSolver, BlockJacobiWorksInsideEigenConjugateGradient) {
  const SpMat A = sheet_matrix(10.0);
  const VecX b = VecX::Random(A.rows());
  Eigen::ConjugateGradient<SpMat, Eigen::Lower | Eigen::Upper, BlockJacobiPreconditioner> cg;
  cg.setTolerance(1e-10);
  cg.compute(A);
  const VecX x = cg.solve(b);
  ASSERT_EQ(cg.info(), Eigen::Success);
  VecX y;
  BlockJacobiPreconditioner M(18);
  M.compute(A);
  const CgResult r = pcg_solve(A, b, y, M, 1e-10, 5000);
  EXPECT_TRUE(r.converged);
  EXPECT_LT((x - y).norm() / y.norm(), 1e-8);
  EXPECT_NEAR(cg.iterations(), r.iterations, 2);
}

TEST(LinearSolver, IndefiniteMatrixIsReportedNotSpd) {
  // Subtract a multiple of the identity large enough to make the matrix indefinite.
  SpMat A = sheet_matrix(10.0);
  SpMat shiftI(A.rows(), A.cols());
  shiftI.setIdentity();
  A = A - 1e4 * shiftI;
  const VecX b = VecX::Random(A.rows());
  for (auto kind : {LinearSolverKind::PlainCG, LinearSolverKind::BlockJacobiCG,
                    LinearSolverKind::DirectLDLT}) {
    LinearSolver ls(kind, 18, 1e-10, 5000);
    VecX x;
    const auto r = ls.solve(A, b, x);
    EXPECT_FALSE(r.ok) << to_string(kind);
    EXPECT_TRUE(r.not_spd) << to_string(kind) << ": " << r.failure;
  }
}

TEST(LinearSolver, NegativeCurvatureIsCaughtEvenWithAnSpdPreconditioner) {
  // diag(1, 1, -1): the identity preconditioner is SPD, CG must see p^T A p <= 0.
  SpMat A(3, 3);
  A.insert(0, 0) = 1;
  A.insert(1, 1) = 1;
  A.insert(2, 2) = -1;
  A.makeCompressed();
  VecX x;
  const CgResult r = pcg_solve(A, VecX::Ones(3), x, IdentityPrecond{}, 1e-12, 10);
  EXPECT_TRUE(r.indefinite);
  EXPECT_FALSE(r.converged);
}
