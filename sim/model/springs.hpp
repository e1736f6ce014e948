// In-plane springs on every mesh edge (paper eq. 3, Appendix B.1):
//     E = 1/2 ks (|x_i - x_j| - s_ij)^2,   F_i = ks (s_ij/|r| - 1) r,   r = x_i - x_j,
//     Hx_ii = -dF_i/dx_i = ks ((1 - s/|r|) I + s/|r|^3 r r^T),  Hx_ij = -Hx_ii.
#pragma once

#include "sim/mesh/mesh.hpp"
#include "sim/model/force_term.hpp"

namespace crumple {

/// The 3x3 block K(r) = (1 - s/|r|) I + s/|r|^3 r r^T shared by springs and dashpots.
inline Mat3 spring_block(const Vec3& r, double s) {
  const double l = r.norm();
  return (1.0 - s / l) * Mat3::Identity() + (s / (l * l * l)) * (r * r.transpose());
}

/// K(r) u without forming the block (the dashpots' force on every explicit step).
inline Vec3 spring_block_times(const Vec3& r, double s, const Vec3& u) {
  const double il = 1.0 / r.norm(), sil = s * il;
  return (1.0 - sil) * u + (sil * il * il * r.dot(u)) * r;
}

class SpringTerm : public ForceTerm {
 public:
  SpringTerm(const Mesh& mesh, double ks);
  std::string name() const override { return "springs"; }
  double energy(const State& s) const override;
  void add_force(const State& s, VecX& f) const override;
  void add_jacobians(const State& s, Jacobians& J) const override;
  void coupled_pairs(std::vector<std::pair<Index, Index>>& out) const override;
  void bind(const BlockPattern& pattern) override;

 private:
  const Mesh* mesh_;
  double ks_;
  PatchColoring colors_;
  std::vector<std::array<BlockSlot, 4>> slots_;  // ii, ij, ji, jj
};

}  // namespace crumple
