// Two-level preconditioner (two_level.hpp): block Jacobi plus the exact solve on the rigid
// motions of node patches.
#include "sim/integrate/two_level.hpp"

#include <algorithm>

namespace crumple {

namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

// Row (i, d) of P restricted to its aggregate's six columns: [e_d ; r_i x e_d]
// (u_d = t_d + (w x r)_d = t_d + w . (r x e_d)).
Vec6 prolongation_row(const Vec3& r, int d) {
  Vec6 p = Vec6::Zero();
  p[d] = 1.0;
  p.tail<3>() = r.cross(Vec3::Unit(d));
  return p;
}

// The entry of `list` keyed b, appended (zero) if absent. Lists hold the few aggregates a row
// or a patch touches, so a linear search is the fastest lookup.
template <class T>
T& entry(std::vector<std::pair<int, T>>& list, int b) {
  for (auto& [key, value] : list)
    if (key == b) return value;
  list.emplace_back(b, T::Zero());
  return list.back().second;
}

}  // namespace

TwoLevelPreconditioner::TwoLevelPreconditioner(int block_size, int aggregate_nodes)
    : fine_(block_size), agg_(std::max(1, aggregate_nodes)) {}

void TwoLevelPreconditioner::compute(const SpMat& A, const VecX& x) {
  failure_.clear();
  info_ = Eigen::Success;
  fine_.compute(A);
  if (fine_.info() != Eigen::Success) {
    info_ = Eigen::NumericalIssue;
    failure_ = "Cholesky of diagonal block " + std::to_string(fine_.failed_block()) + " failed";
    return;
  }
  n_ = A.rows() / 3;
  // The remainder joins the last patch, so every patch has at least agg_ nodes (or all of them).
  num_aggregates_ = static_cast<int>(std::max<Index>(1, n_ / agg_));
  arm_.resize(n_);
#pragma omp parallel for schedule(static)
  for (int a = 0; a < num_aggregates_; ++a) {
    const Index i0 = first(a), i1 = first(a + 1);
    Vec3 c = Vec3::Zero();
    for (Index i = i0; i < i1; ++i) c += x.segment<3>(3 * i);
    c /= static_cast<double>(i1 - i0);
    double L = 0;
    for (Index i = i0; i < i1; ++i) L = std::max(L, (x.segment<3>(3 * i) - c).norm());
    for (Index i = i0; i < i1; ++i) arm_[i] = (x.segment<3>(3 * i) - c) / (L > 0 ? L : 1.0);
  }
  // A patch whose nodes are collinear (or a single node) would give P dependent columns and
  // P^T A P a zero pivot, reported below as not SPD. Patches of agg_ >= 3 consecutive Hilbert
  // nodes of a triangulated sheet are not collinear. The symbolic analysis is kept while the
  // patches couple the same way (it changes with contact pairs only).
  if (coarse_matrix(A)) coarse_ldlt_.analyzePattern(coarse_);
  coarse_ldlt_.factorize(coarse_);
  if (coarse_ldlt_.info() != Eigen::Success || !(coarse_ldlt_.vectorD().minCoeff() > 0.0)) {
    info_ = Eigen::NumericalIssue;
    failure_ = "coarse (patch rigid motion) matrix has a pivot <= 0";
  }
}

bool TwoLevelPreconditioner::coarse_matrix(const SpMat& A) {
  // C(a, b) = sum over i in a, j in b of P_i^T A_ij P_j. Row (i, d) of A times P gives, per
  // neighbouring aggregate b, q_b = sum_j,e A(3i+d, 3j+e) p(j, e); then C(a, b) += p(i, d) q_b^T.
  // Aggregates own contiguous rows, so they are filled in parallel without conflicts.
  const int m = num_aggregates_;
  std::vector<std::vector<std::pair<int, Mat6>>> blocks(m);
#pragma omp parallel for schedule(dynamic, 4)
  for (int a = 0; a < m; ++a) {
    auto& mine = blocks[a];
    std::vector<std::pair<int, Vec6>> q;
    for (Index i = first(a); i < first(a + 1); ++i)
      for (int d = 0; d < 3; ++d) {
        q.clear();
        for (SpMat::InnerIterator it(A, 3 * i + d); it; ++it) {
          const Index j = it.col() / 3;
          entry(q, aggregate_of(j)) += it.value() * prolongation_row(arm_[j], it.col() % 3);
        }
        const Vec6 p = prolongation_row(arm_[i], d);
        for (const auto& [b, qb] : q) entry(mine, b).noalias() += p * qb.transpose();
      }
  }
  std::vector<std::pair<int, int>> pattern;
  std::vector<Eigen::Triplet<double>> trip;
  for (int a = 0; a < m; ++a)
    for (const auto& [b, B] : blocks[a]) {
      pattern.emplace_back(a, b);
      for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c) trip.emplace_back(6 * a + r, 6 * b + c, B(r, c));
    }
  coarse_.resize(6 * m, 6 * m);
  coarse_.setFromTriplets(trip.begin(), trip.end());
  std::sort(pattern.begin(), pattern.end());
  if (pattern == coarse_pattern_) return false;
  coarse_pattern_ = std::move(pattern);
  return true;
}

void TwoLevelPreconditioner::apply(const VecX& r, VecX& z) const {
  fine_.apply(r, z);
  const int m = num_aggregates_;
  rc_.resize(6 * m);
  // Restriction P^T r: per patch, the summed residual force and its moment about c_a.
#pragma omp parallel for schedule(static)
  for (int a = 0; a < m; ++a) {
    const Index i0 = first(a), i1 = first(a + 1);
    Vec3 f = Vec3::Zero(), mom = Vec3::Zero();
    for (Index i = i0; i < i1; ++i) {
      const Vec3 ri = r.segment<3>(3 * i);
      f += ri;
      mom += arm_[i].cross(ri);
    }
    rc_.segment<3>(6 * a) = f;
    rc_.segment<3>(6 * a + 3) = mom;
  }
  yc_ = coarse_ldlt_.solve(rc_);
  // Prolongation: z_i += t_a + w_a x r_i.
#pragma omp parallel for schedule(static)
  for (int a = 0; a < m; ++a) {
    const Index i0 = first(a), i1 = first(a + 1);
    const Vec3 t = yc_.segment<3>(6 * a), w = yc_.segment<3>(6 * a + 3);
    for (Index i = i0; i < i1; ++i) z.segment<3>(3 * i) += t + w.cross(arm_[i]);
  }
}

}  // namespace crumple
