// Linear solvers of the reduced system (sim/integrate/linear_solver.hpp, block_jacobi.hpp):
// all agree on an SPD sheet matrix, block-Jacobi cuts CG iterations, the preconditioner works
// inside Eigen's ConjugateGradient, the two-level preconditioner is what its definition says and
// cuts iterations further, and an indefinite matrix is reported as not SPD.
#include "sim/integrate/linear_solver.hpp"
#include "sim/integrate/pcg.hpp"
#include "sim/mesh/generate.hpp"
#include "sim/model/sheet_model.hpp"
#include "tests/support/grid_mesh.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <gtest/gtest.h>

using namespace crumple;

namespace {

// Hx + Hv / (beta h) of a crumpled sheet: the matrix the integrator solves (positions in *x if
// given). By default a 10 x 10 grid.
SpMat sheet_matrix(double shift, VecX* x = nullptr, const Mesh* on = nullptr) {
  static const Mesh grid = crumple::testing::grid_mesh(10, 10, 1.0, 1.0, 0.15, 5);
  const Mesh& mesh = on ? *on : grid;
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
  if (x) *x = s.x;
  return A;
}

}  // namespace

TEST(LinearSolver, AllSolversAgreeAndBlockJacobiHelps) {
  VecX pos;
  const SpMat A = sheet_matrix(10.0, &pos);
  const VecX b = VecX::Random(A.rows());  // random rhs: a vector of ones hides differences
  VecX ref;
  LinearSolver direct(LinearSolverKind::DirectLDLT, 18, 1e-10, 5000);
  ASSERT_TRUE(direct.solve(A, b, ref).ok);
  int its[4];
  const LinearSolverKind kinds[4] = {LinearSolverKind::PlainCG, LinearSolverKind::BlockJacobiCG,
                                     LinearSolverKind::IncompleteCholeskyCG,
                                     LinearSolverKind::TwoLevelCG};
  for (int k = 0; k < 4; ++k) {
    LinearSolver ls(kinds[k], 18, 1e-10, 5000, 20);
    VecX x;
    const auto r = ls.solve(A, b, x, &pos);
    ASSERT_TRUE(r.ok) << to_string(kinds[k]) << ": " << r.failure;
    EXPECT_LT((x - ref).norm() / ref.norm(), 1e-7) << to_string(kinds[k]);
    its[k] = r.iterations;
  }
  std::printf("CG iterations: plain %d, block Jacobi(18) %d, incomplete Cholesky %d, two-level %d\n",
              its[0], its[1], its[2], its[3]);
  EXPECT_LT(its[1], its[0]);
}

TEST(LinearSolver, TwoLevelIsBlockJacobiPlusTheExactPatchRigidMotionSolve) {
  // The preconditioner against its definition, built densely here: P's columns are the
  // translations and rotations (about the centroid, arms scaled by the patch radius) of runs
  // of 20 nodes, the last run taking the remainder (100 nodes: five patches).
  VecX x;
  const SpMat A = sheet_matrix(10.0, &x);
  const Eigen::MatrixXd dense(A);
  const int agg = 20, n = static_cast<int>(x.size() / 3), m = n / agg;
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(3 * n, 6 * m);
  for (int a = 0; a < m; ++a) {
    const int i0 = a * agg, i1 = a == m - 1 ? n : i0 + agg;
    Vec3 c = Vec3::Zero();
    for (int i = i0; i < i1; ++i) c += x.segment<3>(3 * i);
    c /= i1 - i0;
    double L = 0;
    for (int i = i0; i < i1; ++i) L = std::max(L, (x.segment<3>(3 * i) - c).norm());
    for (int i = i0; i < i1; ++i) {
      const Vec3 r = (x.segment<3>(3 * i) - c) / L;
      for (int k = 0; k < 3; ++k) {
        P.block<3, 1>(3 * i, 6 * a + k) = Vec3::Unit(k);
        P.block<3, 1>(3 * i, 6 * a + 3 + k) = Vec3::Unit(k).cross(r);  // rotation about axis k
      }
    }
  }
  const Eigen::MatrixXd C = P.transpose() * dense * P;
  const VecX r = VecX::Random(A.rows());
  VecX expect(r.size());
  for (int start = 0; start < A.rows(); start += 18) {
    const int size = std::min<int>(18, A.rows() - start);
    expect.segment(start, size) =
        dense.block(start, start, size, size).llt().solve(r.segment(start, size));
  }
  expect += P * C.llt().solve(P.transpose() * r);
  TwoLevelPreconditioner M(18, agg);
  M.compute(A, x);
  ASSERT_EQ(M.info(), Eigen::Success) << M.failure();
  EXPECT_EQ(M.num_aggregates(), m);
  const VecX z = M.solve(r);
  EXPECT_LT((z - expect).norm() / expect.norm(), 1e-10);
}

TEST(LinearSolver, TwoLevelCutsCgIterationsOnALargerSheet) {
  // A disk of 1000 nodes on the generator's Hilbert order, as the simulator meshes it, with
  // little damping against the stiffness (1 / (beta h) = 0.01 b_iso), as in quasistatic steps
  // of milliseconds. Block Jacobi must carry the sheet-wide modes one block at a time; the
  // coarse space removes them (measured: 891 against 155 iterations; at 10 b_iso, where the
  // damping dominates and there is little to remove, 96 against 73).
  const Mesh disk = generate_mesh(MeshSpec{"disk", 1.0, 1000, 1});
  VecX pos;
  const SpMat A = sheet_matrix(0.01, &pos, &disk);
  const VecX b = VecX::Random(A.rows());
  LinearSolver bj(LinearSolverKind::BlockJacobiCG, 18, 1e-8, 20000);
  LinearSolver two(LinearSolverKind::TwoLevelCG, 18, 1e-8, 20000, 32);
  VecX x1, x2;
  const auto r1 = bj.solve(A, b, x1);
  const auto r2 = two.solve(A, b, x2, &pos);
  ASSERT_TRUE(r1.ok && r2.ok) << r1.failure << r2.failure;
  std::printf("%d nodes, CG iterations to 1e-8: block Jacobi(18) %d, two-level (32-node patches) %d\n",
              disk.num_nodes(), r1.iterations, r2.iterations);
  EXPECT_LT((x1 - x2).norm() / x1.norm(), 1e-6);
  EXPECT_LT(3 * r2.iterations, r1.iterations);
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

TEST(LinearSolver, BlockJacobiAppliesTheInverseOfEachDiagonalBlock) {
  // 121 nodes = 363 rows: 18 leaves a partial last block of 3 rows, 144 one of 75.
  const SpMat A = sheet_matrix(10.0);
  const Eigen::MatrixXd dense(A);
  const VecX r = VecX::Random(A.rows());
  for (const int bs : {18, 144, 7}) {
    BlockJacobiPreconditioner M(bs);
    M.compute(A);
    ASSERT_EQ(M.info(), Eigen::Success);
    VecX expect(r.size());
    for (Eigen::Index start = 0; start < A.rows(); start += bs) {
      const Eigen::Index size = std::min<Eigen::Index>(bs, A.rows() - start);
      expect.segment(start, size) =
          dense.block(start, start, size, size).ldlt().solve(r.segment(start, size));
    }
    const VecX z = M.solve(r);
    EXPECT_LT((z - expect).norm() / expect.norm(), 1e-12) << "block size " << bs;
    VecX z2 = VecX::Zero(r.size());
    M.apply(r, z2);
    EXPECT_EQ(z, z2) << "block size " << bs;
  }
}

TEST(LinearSolver, IndefiniteMatrixIsReportedNotSpd) {
  // Subtract a multiple of the identity large enough to make the matrix indefinite.
  SpMat A = sheet_matrix(10.0);
  SpMat shiftI(A.rows(), A.cols());
  shiftI.setIdentity();
  A = A - 1e4 * shiftI;
  const VecX b = VecX::Random(A.rows());
  VecX pos;
  sheet_matrix(10.0, &pos);
  for (auto kind : {LinearSolverKind::PlainCG, LinearSolverKind::BlockJacobiCG,
                    LinearSolverKind::DirectLDLT, LinearSolverKind::TwoLevelCG}) {
    LinearSolver ls(kind, 18, 1e-10, 5000);
    VecX x;
    const auto r = ls.solve(A, b, x, &pos);
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
