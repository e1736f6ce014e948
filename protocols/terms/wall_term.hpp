// A wall acting on every node as a ForceTerm (one-sided potential of wall.hpp):
//     U(d) = k/3 (range - d)^3 for d < range, 0 beyond.
// The term also reports the reaction force on the wall (minus the sum of node forces), which
// compress stages use to detect contact and log the load.
#pragma once

#include "protocols/terms/wall.hpp"
#include "sim/model/force_term.hpp"

#include <memory>

namespace crumple {

/// How the repulsion grows with the penetration pen = range - d (d the signed distance):
///  Cubic:      U = k/3 pen^3, F = k pen^2 (a stiff wall);
///  Saturating: F = f_max (1 - exp(-pen/w))^2, U its integral (a bounded push, such as the
///              paper's radial cutoff force, which self-contact can resist).
/// Both give a C^2 energy at pen = 0.
struct WallProfile {
  enum class Kind { Cubic, Saturating } kind = Kind::Cubic;
  double k = 1.0;      ///< Cubic: stiffness
  double f_max = 1.0;  ///< Saturating: largest force
  double width = 1.0;  ///< Saturating: penetration over which the force builds up
  /// Energy, force magnitude -dU/dd and its derivative dF/dpen at penetration pen >= 0.
  void eval(double pen, double& U, double& F, double& dF) const;
};

class WallTerm : public ForceTerm {
 public:
  /// k: stiffness of the cubic potential (force k range^2 at contact); range: its reach.
  WallTerm(std::shared_ptr<const Wall> wall, Index num_nodes, double k, double range);
  WallTerm(std::shared_ptr<const Wall> wall, Index num_nodes, WallProfile profile, double range);
  std::string name() const override { return wall_->name() + " wall"; }
  double energy(const State& s) const override;
  void add_force(const State& s, VecX& f) const override;
  void add_jacobians(const State& s, Jacobians& J) const override;
  void coupled_pairs(std::vector<std::pair<Index, Index>>&) const override {}
  void bind(const BlockPattern& pattern) override;

  const Wall& wall() const { return *wall_; }
  /// Total force the nodes exert on the wall (the load on a piston).
  Vec3 reaction(const State& s) const;
  /// Smallest signed distance of any node to the wall.
  double min_distance(const State& s) const;

 private:
  std::shared_ptr<const Wall> wall_;
  Index n_;
  WallProfile profile_;
  double range_;
  std::vector<BlockSlot> slots_;
};

}  // namespace crumple
