// Fold barrier: keeps a hinge from closing completely and folding through itself.
//
// Contact sites of adjacent triangles never interact (contact_sites.hpp), and the bending force
// vanishes at a complete fold: with c = 2 sin(theta/2), dc/dtheta = cos(theta/2) = 0 at
// theta = pi. So nothing stops a hinge from passing theta = pi, after which the triangles around
// it cross one another (radial confinement of a 3000-node disk into a ball left 2-3 crossings,
// each next to a hinge folded to 176-180 degrees). This term is the missing piece of
// self-avoidance at the scale of one hinge: with the opening psi = pi - |theta| of the fold,
//     E_h = K (psi0_h - psi)^3 / (psi0_h^2 (psi + delta))   for psi < psi0_h, 0 otherwise,
// which is C^2 at psi0_h and steep but finite at a complete fold (delta = 0.02 psi0_h: E(0) =
// 50 K and |dE/dpsi| = 2650 K / psi0 there, i.e. a force of about 2650 ks sigma on a wing tip,
// far above the largest contact force 0.54 ks sigma). A finite barrier keeps every force finite when a step lands next to
// theta = pi (an unbounded one gave non-finite explicit stages). The opening at which it starts,
// psi0_h = sigma / w_h with w_h the smaller rest altitude of the two wings over the hinge edge
// (capped at pi/2), is where the two layers of the fold come within the contact range sigma of
// each other, and K = ks sigma^2 is the scale of the contact energy (contact_potential.hpp).
// With psi' = -sign(theta) theta' (hinge_geometry.hpp gives theta's gradient and Hessian):
//     F = -E'(psi) grad psi,   Hx = E''(psi) grad theta grad theta^T - E'(psi) sign(theta) H(theta).
// Hinges far from a complete fold cost two cross products per evaluation (a test on cos theta
// without the bend angle itself).
#pragma once

#include "sim/mesh/mesh.hpp"
#include "sim/model/force_term.hpp"

#include <utility>
#include <vector>

namespace crumple {

class FoldBarrierTerm : public ForceTerm {
 public:
  /// Keeps a reference to mesh (it must outlive the term).
  FoldBarrierTerm(const Mesh& mesh, double ks, double sigma);

  std::string name() const override { return "fold_barrier"; }
  double energy(const State& s) const override;
  void add_force(const State& s, VecX& f) const override;
  void add_jacobians(const State& s, Jacobians& J) const override;
  /// The hinge stencils (already coupled by bending).
  void coupled_pairs(std::vector<std::pair<Index, Index>>& out) const override;
  void bind(const BlockPattern& pattern) override;

  /// Opening below which hinge h is pushed open.
  double onset(Index h) const { return psi0_[h]; }
  /// Hinges with psi < psi0 at x, ascending.
  std::vector<Index> active_hinges(const VecX& x) const;

 private:
  /// (hinge, bend angle) of every hinge with psi < psi0 at x, ascending: a test on cos theta
  /// per hinge, in parallel, then the bend angle of those that pass.
  std::vector<std::pair<Index, double>> near_complete_folds(const VecX& x) const;

  const Mesh* mesh_;
  double K_;
  std::vector<double> psi0_;
  std::vector<double> cos_onset_sq_;  ///< cos^2(psi0), slightly lowered (near_complete_folds)
  std::vector<std::array<BlockSlot, 16>> slots_;
};

}  // namespace crumple
