// Test helper: harmonic anchors E = 1/2 k sum_i |x_i - a_i|^2 on chosen nodes. With k > 0 it
// holds a prescribed shape (a fold); with k < 0 it is a concave potential that makes the
// Newton matrix indefinite for large steps.
#pragma once

#include "sim/model/force_term.hpp"

namespace crumple::testing {

class AnchorTerm : public ForceTerm {
 public:
  AnchorTerm(std::vector<Index> nodes, VecX targets, double k)
      : nodes_(std::move(nodes)), targets_(std::move(targets)), k_(k) {}
  std::string name() const override { return "anchor"; }
  double energy(const State& s) const override {
    double e = 0;
    for (std::size_t a = 0; a < nodes_.size(); ++a)
      e += 0.5 * k_ * (node(s.x, nodes_[a]) - targets_.segment<3>(3 * a)).squaredNorm();
    return e;
  }
  void add_force(const State& s, VecX& f) const override {
    for (std::size_t a = 0; a < nodes_.size(); ++a)
      f.segment<3>(3 * nodes_[a]) -= k_ * (node(s.x, nodes_[a]) - targets_.segment<3>(3 * a));
  }
  void add_jacobians(const State&, Jacobians& J) const override {
    for (const auto& sl : slots_) add_block(J.Hx.valuePtr(), sl, k_ * Mat3::Identity());
  }
  void coupled_pairs(std::vector<std::pair<Index, Index>>&) const override {}
  void bind(const BlockPattern& p) override {
    slots_.clear();
    for (Index i : nodes_) slots_.push_back(p.slot(i, i));
  }

 private:
  std::vector<Index> nodes_;
  VecX targets_;
  double k_;
  std::vector<BlockSlot> slots_;
};

}  // namespace crumple::testing
