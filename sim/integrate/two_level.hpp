// Two-level preconditioner: block Jacobi (block_jacobi.hpp) plus a coarse correction on the
// rigid motions of aggregates of nodes (additive two-level Schwarz),
//     M^{-1} r = B^{-1} r + P (P^T A P)^{-1} P^T r.
// Aggregates are runs of `aggregate_nodes` consecutive nodes; on the mesh's Hilbert order they
// are compact patches. P has six columns per aggregate a: the three translations and the three
// infinitesimal rotations about the patch centroid c_a at the current positions, so node i of
// aggregate a moves by t_a + w_a x r_i, r_i = (x_i - c_a) / L_a (L_a the patch radius, which
// keeps the columns of one scale).
//
// Why: block Jacobi only sees a few neighbouring nodes, so CG still has to carry the sheet's
// long-wavelength bending and in-plane modes across the whole sheet one block at a time, and its
// iteration count grows with the node count. Patches that bend are, locally, patches that
// rotate: the coarse space of patch rigid motions holds those smooth modes, and the exact
// coarse solve removes them. Measured on the reduced Newton matrix of the radial sheet at
// 3000 nodes (bench_precond, relative residual 1e-2): 768 CG iterations with block Jacobi 18,
// 75 with 32-node patches, the solve 6-8x shorter including the coarse setup.
//
// In the hybrid integrator it is an option (linear_solver: two_level), not the default: it
// also finds the negative curvature of a buckling mode that a loosely converged block-Jacobi
// CG can stop short of (the coarse factorisation sees smooth modes at once), so near buckling
// it refuses more quasistatic steps, and over radial confinement runs the shorter solves were
// spent on those (bench_radial; see docs/CONFIG.md).
//
// Both parts are SPD when A is: the Galerkin matrix P^T A P of an SPD A is SPD for a P of full
// column rank. A non-positive pivot of its LDL^T therefore proves A is not SPD (as does a failed
// diagonal block), and info() reports NumericalIssue for the integrator to reject the step.
#pragma once

#include "sim/integrate/block_jacobi.hpp"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <string>
#include <vector>

namespace crumple {

class TwoLevelPreconditioner {
 public:
  TwoLevelPreconditioner(int block_size, int aggregate_nodes);

  /// Factors the blocks of A and the coarse matrix P^T A P for the node positions x (3n).
  void compute(const SpMat& A, const VecX& x);
  Eigen::ComputationInfo info() const { return info_; }
  /// Which part found A not SPD, for the rejection message.
  const std::string& failure() const { return failure_; }

  /// z = M^{-1} r.
  void apply(const VecX& r, VecX& z) const;
  VecX solve(const VecX& r) const {
    VecX z;
    apply(r, z);
    return z;
  }

  int num_aggregates() const { return num_aggregates_; }
  int aggregate_nodes() const { return agg_; }

 private:
  /// Assembles coarse_ = P^T A P; true when its block pattern differs from the last one.
  bool coarse_matrix(const SpMat& A);
  /// First node of patch a (a = num_aggregates_ gives n_): runs of agg_ nodes, the last one
  /// also takes the remainder.
  Index first(int a) const { return a >= num_aggregates_ ? n_ : static_cast<Index>(a) * agg_; }
  int aggregate_of(Index node) const {
    return static_cast<int>(std::min<Index>(node / agg_, num_aggregates_ - 1));
  }

  BlockJacobiPreconditioner fine_;
  int agg_;
  int num_aggregates_ = 0;
  Eigen::Index n_ = 0;  // nodes
  std::vector<Vec3> arm_;          // r_i per node
  SpMatCol coarse_;
  std::vector<std::pair<int, int>> coarse_pattern_;  // coupled patch pairs, sorted
  Eigen::SimplicialLDLT<SpMatCol> coarse_ldlt_;
  Eigen::ComputationInfo info_ = Eigen::Success;
  std::string failure_;
  mutable VecX rc_, yc_;
};

}  // namespace crumple
