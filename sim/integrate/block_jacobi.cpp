// Block-Jacobi preconditioner (block_jacobi.hpp).
#include "sim/integrate/block_jacobi.hpp"

#include <algorithm>

namespace crumple {

void BlockJacobiPreconditioner::factor(const SpMat& A) {
  n_ = A.rows();
  const int bs = std::max(1, block_size_);
  const int nb = static_cast<int>((n_ + bs - 1) / bs);
  blocks_.resize(nb);
  int failed = nb;
#pragma omp parallel for schedule(static) reduction(min : failed)
  for (int b = 0; b < nb; ++b) {
    const Eigen::Index start = static_cast<Eigen::Index>(b) * bs;
    const Eigen::Index size = std::min<Eigen::Index>(bs, n_ - start);
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(size, size);
    for (Eigen::Index r = start; r < start + size; ++r)
      for (SpMat::InnerIterator it(A, r); it; ++it)
        if (it.col() >= start && it.col() < start + size) D(r - start, it.col() - start) = it.value();
    blocks_[b].compute(D);
    if (blocks_[b].info() != Eigen::Success) failed = std::min(failed, b);
  }
  failed_block_ = failed < nb ? failed : -1;
  info_ = failed_block_ < 0 ? Eigen::Success : Eigen::NumericalIssue;
}

VecX BlockJacobiPreconditioner::solve(const VecX& r) const {
  VecX z(r.size());
  const int bs = std::max(1, block_size_);
  const int nb = static_cast<int>(blocks_.size());
#pragma omp parallel for schedule(static)
  for (int b = 0; b < nb; ++b) {
    const Eigen::Index start = static_cast<Eigen::Index>(b) * bs;
    const Eigen::Index size = std::min<Eigen::Index>(bs, n_ - start);
    z.segment(start, size) = blocks_[b].solve(r.segment(start, size));
  }
  return z;
}

}  // namespace crumple
