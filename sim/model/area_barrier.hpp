// Area barrier: keeps a triangle from being pressed flat into a line.
//
// The edge springs (springs.hpp) alone do not resist the collapse of a triangle: three edge
// lengths a, b, a + b are a degenerate triangle at a finite spring energy (a collapse seen under
// the deepest axial compaction, Δ̃ = 0.045, left edges strained -21 %, -17 % and +12 %). As the
// area goes to zero the triangle's normal, and with it the bend angle of its three hinges, loses
// its meaning and the bending force diverges (4.7e6 N against 36 N of springs at the failing
// node). This term is the in-plane counterpart of the fold barrier (sim/contact/fold_barrier.hpp).
// With n = (x1 - x0) x (x2 - x0) the triangle's doubled-area vector and n0 its rest value, the
// squared area ratio q = |n|^2 / |n0|^2 is a polynomial in the positions (smooth also at zero
// area, where |n| is not), and
//     E_t = K_t (q0 - q)^3 / (q0^2 (q + delta))   for q < q0, 0 otherwise,
// the same C^2 barrier as the fold barrier's (barrier_function.hpp), with q0 = a0^2 (a0 the area ratio at which it
// starts, 1/2) and delta = 0.02 q0: E(0) = 50 K_t. K_t = ks l_t^2, l_t^2 the mean squared rest
// edge of the triangle, makes a collapse cost some 100 times the energy of an edge stretched to
// twice its length. The triangles of every kept run at Δ̃ >= 0.09 stayed above 0.77 of their
// rest area in all stored frames, so there the term never acts.
// Derivatives (docs/MODEL.md §2.6): with d_i = x_{i+2} - x_{i+1} (indices mod 3),
//     dn/dx_i = [d_i]_x,   d|n|^2/dx_i = 2 n x d_i,
//     d^2|n|^2/dx_i dx_j = 2 (-[d_i]_x [d_j]_x + s_ij [n]_x),  s_ij = +1 (j = i+2), -1 (j = i+1),
// 0 (j = i); F = -E'(q) grad q and Hx = E''(q) grad q grad q^T + E'(q) Hess q.
#pragma once

#include "sim/mesh/mesh.hpp"
#include "sim/model/force_term.hpp"

#include <vector>

namespace crumple {

class AreaBarrierTerm : public ForceTerm {
 public:
  /// The area ratio below which the barrier acts.
  static constexpr double kOnset = 0.5;

  /// Keeps a reference to mesh (it must outlive the term).
  AreaBarrierTerm(const Mesh& mesh, double ks, double onset = kOnset);

  std::string name() const override { return "area_barrier"; }
  double energy(const State& s) const override;
  void add_force(const State& s, VecX& f) const override;
  void add_jacobians(const State& s, Jacobians& J) const override;
  /// The triangles' node pairs (already coupled by the springs).
  void coupled_pairs(std::vector<std::pair<Index, Index>>& out) const override;
  void bind(const BlockPattern& pattern) override;

  /// Triangles with area below onset times their rest area at x, ascending.
  std::vector<Index> active_triangles(const VecX& x) const;
  /// The squared area ratio q = |n|^2 / |n0|^2 of triangle t at x.
  double squared_area_ratio(const VecX& x, Index t) const;

 private:
  const Mesh* mesh_;
  double q0_;
  std::vector<double> n0_sq_;  ///< |n0|^2 = (2 A0)^2 per triangle
  std::vector<double> limit_;  ///< q0 |n0|^2: active while |n|^2 is below it
  std::vector<double> K_;      ///< ks l_t^2 per triangle
  std::vector<std::array<BlockSlot, 9>> slots_;
};

}  // namespace crumple
