// Dissipative forces (paper §2.3; Appendix B.2). Neither has an energy.
//
// Isotropic drag (8):  F_i = -b_iso v_i,  Hv = b_iso I.
// Internal damping (9): a dashpot parallel to each spring,
//     F_i = -b_int d/dt (r - s r_hat) = -b_int K(r) u,  u = v_i - v_j,
//     K(r) = (1 - s/|r|) I + s/|r|^3 r r^T  (the spring block / ks, "proportional damping"),
// so Hv_ii = b_int K(r) and Hx_ii = b_int s/|r|^3 (u r^T + r u^T + (r.u) I - 3 (r.u)/|r|^2 r r^T)
// (B.6-B.7); the off-diagonal blocks are minus the diagonal ones.
#pragma once

#include "sim/mesh/mesh.hpp"
#include "sim/model/force_term.hpp"

namespace crumple {

class DragTerm : public ForceTerm {
 public:
  DragTerm(Index num_nodes, double b_iso);
  std::string name() const override { return "isotropic drag"; }
  bool conservative() const override { return false; }
  double energy(const State&) const override { return 0.0; }
  void add_force(const State& s, VecX& f) const override;
  void add_jacobians(const State& s, Jacobians& J) const override;
  void coupled_pairs(std::vector<std::pair<Index, Index>>&) const override {}
  void bind(const BlockPattern& pattern) override;

 private:
  Index n_;
  double b_;
  std::vector<BlockSlot> slots_;
};

class InternalDampingTerm : public ForceTerm {
 public:
  InternalDampingTerm(const Mesh& mesh, double b_int);
  std::string name() const override { return "internal damping"; }
  bool conservative() const override { return false; }
  double energy(const State&) const override { return 0.0; }
  void add_force(const State& s, VecX& f) const override;
  void add_jacobians(const State& s, Jacobians& J) const override;
  void coupled_pairs(std::vector<std::pair<Index, Index>>& out) const override;
  void bind(const BlockPattern& pattern) override;

 private:
  const Mesh* mesh_;
  double b_;
  PatchColoring colors_;
  std::vector<std::array<BlockSlot, 4>> slots_;
};

}  // namespace crumple
