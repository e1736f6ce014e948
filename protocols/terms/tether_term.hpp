// Tethers: springs pulling chosen nodes towards target positions, with a stiffness ramped up
// linearly in time so the sheet is led, not yanked (used by roll and unfold stages):
//     E = 1/2 k(t) sum_i |x_i - X_i(t)|^2,   k(t) = k_max min(1, max(0, (t - t0)/t_ramp)).
// Targets may move (a function of time per node set), e.g. to wrap the sheet onto a cylinder.
#pragma once

#include "sim/model/force_term.hpp"

#include <functional>

namespace crumple {

class TetherTerm : public ForceTerm {
 public:
  /// nodes: the tethered nodes; targets(t, out): fills out (3 x nodes.size()) with the targets.
  using TargetFn = std::function<void(double t, Eigen::Matrix3Xd& out)>;
  TetherTerm(std::vector<Index> nodes, TargetFn targets, double k_max, double t0, double t_ramp);
  std::string name() const override { return "tethers"; }
  double energy(const State& s) const override;
  void add_force(const State& s, VecX& f) const override;
  void add_jacobians(const State& s, Jacobians& J) const override;
  void coupled_pairs(std::vector<std::pair<Index, Index>>&) const override {}
  void bind(const BlockPattern& pattern) override;

  double stiffness(double t) const;
  /// Largest distance of a tethered node from its target.
  double max_deviation(const State& s) const;

 private:
  const Eigen::Matrix3Xd& targets_at(double t) const;
  std::vector<Index> nodes_;
  TargetFn targets_;
  double k_max_, t0_, t_ramp_;
  std::vector<BlockSlot> slots_;
  mutable Eigen::Matrix3Xd cache_;
  mutable double cache_t_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace crumple
