// One Newton linearisation of the quasistatic BDF system with plasticity, reduced to a single
// SPD solve for dx (paper eq. 31-35).
//
// Unknowns at t_{k+1}: x, v (3n each), p (one per hinge). With bh = beta h and the history sums
// hx = sum_j alpha_j x_{k-j}, hp = sum_j alpha_j p_{k-j} (bdf.hpp), the residuals are
//     r_x = x + hx - bh v,   r_p = p + hp - bh g(c(x), p),   r_alg = -F(x, v, p).
// The Newton matrix (34) has blocks [I, -bh I, 0; bh Gx, 0, I + bh Gp; Hx, Hv, Hp] with
// Gx = -dg/dx, Gp = -dg/dp (diagonal). Eliminating dv and dp leaves (35):
//     A dx = b,  A = Hx + Hv / bh - bh Hp D Gx,  b = F - Hv r_x / bh + Hp D r_p,
//     D = (I + bh Gp)^{-1},
//     dp = -D (r_p + bh Gx dx),  dv = (r_x + dx) / bh.
// For hinge h, Hp's column is -kb f_h grad c_h and Gx's row is -g'_h grad c_h^T (g'_h = dg/dc),
// so -bh Hp D Gx = -sum_h bh kb f_h D_h g'_h grad c_h grad c_h^T: one rank-1 12 x 12 block per
// hinge on the hinge's stencil, added into A through the pattern's slots (A has exactly the
// sparsity of Hx). g'_h >= 0, so the term softens the bending stiffness, but never below zero:
// bh g' D = bh g' / (1 + bh g') < 1. Only hinges outside the dead band (g'_h != 0) contribute.
#pragma once

#include "sim/integrate/plasticity.hpp"
#include "sim/model/sheet_model.hpp"

namespace crumple {

class ReducedNewton {
 public:
  ReducedNewton(const SheetModel& model, const PlasticLaw& law);

  /// Recomputes the hinge slots. linearise() calls it when the model's pattern was rebuilt
  /// since (SheetModel::pattern_serial), by the integrator or anyone else.
  void bind();

  /// Linearises at s (s.t is t_{k+1}); hx, hp are the history sums, bh = beta h.
  void linearise(const State& s, double bh, const VecX& hx, const VecX& hp);

  const SpMat& matrix() const { return A_; }  ///< A (3n x 3n)
  const VecX& rhs() const { return b_; }      ///< b (3n)
  const VecX& force() const { return F_; }    ///< F at the iterate
  const VecX& r_x() const { return rx_; }
  const VecX& r_p() const { return rp_; }
  const VecX& curvature() const { return c_; }
  const std::vector<Vec12>& curvature_gradient() const { return grad_; }
  const VecX& dg_dc() const { return dg_; }   ///< g'_h per hinge
  const Jacobians& jacobians() const { return J_; }

  /// dv and dp from the solution dx of A dx = b (eq. 35, steps 2-3).
  void recover(const VecX& dx, VecX& dv, VecX& dp) const;

 private:
  const SheetModel& model_;
  PlasticLaw law_;
  PatchColoring hinge_colors_;  // lock-free parallel rank-1 updates (edge_colors.hpp)
  std::vector<std::array<BlockSlot, 16>> slots_;
  std::uint64_t bound_serial_ = 0;  // model_.pattern_serial() at the last bind()
  double bh_ = 0;
  Jacobians J_;
  SpMat A_;
  VecX b_, F_, rx_, rp_, c_, dg_, D_;
  std::vector<Vec12> grad_;
};

}  // namespace crumple
