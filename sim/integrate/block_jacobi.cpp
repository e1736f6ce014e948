// Block-Jacobi preconditioner (block_jacobi.hpp).
#include "sim/integrate/block_jacobi.hpp"

#include <algorithm>

namespace crumple {

void BlockJacobiPreconditioner::factor(const SpMat& A) {
  n_ = A.rows();
  const int bs = std::max(1, block_size_);
  const int nb = static_cast<int>((n_ + bs - 1) / bs);
  num_blocks_ = nb;
  inverses_.resize(static_cast<std::size_t>(nb) * bs * bs);
  int failed = nb;
#pragma omp parallel for schedule(static) reduction(min : failed)
  for (int b = 0; b < nb; ++b) {
    const Eigen::Index start = static_cast<Eigen::Index>(b) * bs;
    const Eigen::Index size = std::min<Eigen::Index>(bs, n_ - start);
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(size, size);
    for (Eigen::Index r = start; r < start + size; ++r)
      for (SpMat::InnerIterator it(A, r); it; ++it)
        if (it.col() >= start && it.col() < start + size) D(r - start, it.col() - start) = it.value();
    const Eigen::LLT<Eigen::MatrixXd> llt(D);
    Eigen::Map<Eigen::MatrixXd> inv(inverses_.data() + static_cast<std::size_t>(b) * bs * bs, size,
                                    size);
    if (llt.info() != Eigen::Success) {
      failed = std::min(failed, b);
      inv.setZero();
      continue;
    }
    inv.setIdentity();
    llt.solveInPlace(inv);
  }
  failed_block_ = failed < nb ? failed : -1;
  info_ = failed_block_ < 0 ? Eigen::Success : Eigen::NumericalIssue;
}

namespace {

// z_b = inv_b r_b for every block; S > 0 fixes the block size at compile time (full blocks).
template <int S>
void apply_blocks(const double* inverses, int bs, Eigen::Index n, int nb, const VecX& r, VecX& z) {
#pragma omp parallel for schedule(static)
  for (int b = 0; b < nb; ++b) {
    const Eigen::Index start = static_cast<Eigen::Index>(b) * bs;
    const Eigen::Index size = std::min<Eigen::Index>(bs, n - start);
    const double* inv = inverses + static_cast<std::size_t>(b) * bs * bs;
    if constexpr (S > 0) {
      if (size == S) {
        z.segment<S>(start).noalias() =
            Eigen::Map<const Eigen::Matrix<double, S, S>>(inv) * r.segment<S>(start);
        continue;
      }
    }
    z.segment(start, size).noalias() =
        Eigen::Map<const Eigen::MatrixXd>(inv, size, size) * r.segment(start, size);
  }
}

}  // namespace

void BlockJacobiPreconditioner::apply(const VecX& r, VecX& z) const {
  z.resize(r.size());
  const int bs = std::max(1, block_size_);
  // 18 (6 nodes) is the default block; other sizes take Eigen's dynamic-size product.
  if (bs == 18)
    apply_blocks<18>(inverses_.data(), bs, n_, num_blocks_, r, z);
  else
    apply_blocks<0>(inverses_.data(), bs, n_, num_blocks_, r, z);
}

VecX BlockJacobiPreconditioner::solve(const VecX& r) const {
  VecX z;
  apply(r, z);
  return z;
}

}  // namespace crumple
