// Bending with plastic rest curvature (paper eq. 15; Appendix B.4; docs/MODEL.md §4).
//
// For each hinge h with bend angle theta (hinge_geometry.hpp), the dimensionless curvature is
// c = 2 sin(theta/2) (signed as theta, eq. 14 and 17) and the energy is
//     E_h = 1/2 kb f_h (c - p_h)^2,   f_h = sqrt(3)|e0|^2 / (2 Abar)  (rest state).
// With dc = cos(theta/2) d theta and d^2c = cos(theta/2) H(theta) - 1/2 sin(theta/2) dtheta
// dtheta^T, the force is F = -zeta grad(theta) and the Hessian is
//     Hx = zeta H(theta) + xi grad(theta) grad(theta)^T,
//     zeta = kb f (c - p) cos(theta/2),  xi = kb f (cos^2(theta/2) - 1/2 (c - p) sin(theta/2)),
// and Hp = -dF/dp = -kb f grad(c). The zeta H(theta) part is assembled per triangle
// (docs/MODEL.md §4.5: each triangle sums the half-hinge Hessians of its three edges
// before writing its 9 blocks once) or, for comparison, per hinge.
#pragma once

#include "sim/mesh/mesh.hpp"
#include "sim/model/force_term.hpp"
#include "sim/model/hinge_geometry.hpp"

namespace crumple {

class BendingTerm : public ForceTerm {
 public:
  enum class Assembly { PerTriangle, PerHinge };
  BendingTerm(const Mesh& mesh, double kb, Assembly assembly = Assembly::PerTriangle);

  std::string name() const override { return "bending"; }
  double energy(const State& s) const override;
  void add_force(const State& s, VecX& f) const override;
  void add_jacobians(const State& s, Jacobians& J) const override;
  void coupled_pairs(std::vector<std::pair<Index, Index>>& out) const override;
  void bind(const BlockPattern& pattern) override;

  /// The per-triangle assembly reads each half hinge in its triangle's own vertex order, so it
  /// needs a consistently oriented mesh (build_mesh makes one); on any other mesh the term
  /// assembles per hinge whatever was asked for.
  Assembly assembly() const { return assembly_; }
  void set_assembly(Assembly a) { assembly_ = oriented_ ? a : Assembly::PerHinge; }

  /// Signed curvature c = 2 sin(theta/2) of every hinge (size n_hinges).
  void curvatures(const VecX& x, VecX& c) const;
  /// The curvatures of the state of the latest add_force or add_jacobians call (the per-hinge
  /// assembly without Hp excepted).
  /// The explicit right-hand side needs c for the plastic rate of the very state whose force it
  /// has just evaluated; recomputing it (curvatures()) took about 15 % of an explicit step at
  /// 12000 nodes.
  const VecX& last_curvatures() const;
  /// c and its gradient (12 entries over the hinge's nodes x0..x3) for every hinge.
  void curvature_gradients(const VecX& x, VecX& c, std::vector<Vec12>& grad) const;

  double kb() const { return kb_; }
  /// Whether the force path computes each triangle's normal once for all its hinges (an
  /// oriented mesh) rather than once per hinge.
  bool shares_triangle_frames() const { return oriented_; }

 private:
  struct HingeCache {
    double cos_half, zeta, xi;  // c itself is in curvature_
    Vec12 grad;  // d theta / dx over the hinge's 4 nodes
  };
  /// Every hinge's cache, of the Jacobians (and the curvatures).
  void update_cache(const State& s) const;
  /// frames_ at x (oriented meshes).
  void update_frames(const VecX& x) const;
  /// theta's gradient of hinge h at x and its half-angle sine and cosine; on an oriented mesh
  /// from frames_, which must be those of x.
  HalfAngle hinge_gradient(const VecX& x, Index h, Vec12& grad) const;

  const Mesh* mesh_;
  double kb_;
  Assembly assembly_;
  PatchColoring hinge_colors_, tri_colors_;
  std::vector<std::array<BlockSlot, 16>> hinge_slots_;
  std::vector<std::array<BlockSlot, 9>> tri_slots_;
  mutable std::vector<HingeCache> cache_;
  mutable VecX curvature_;  ///< c of every hinge at the latest force or Jacobian evaluation
  // Whether every hinge's T1 = (x0, x1, x2) and T2 = (x1, x0, x3) run as their mesh
  // triangles do (a consistently oriented mesh, checked at construction). Then the force path
  // shares each triangle's normal (frames_, of the latest evaluation) between its hinges.
  bool oriented_ = false;
  mutable std::vector<TriangleFrame> frames_;
};

}  // namespace crumple
