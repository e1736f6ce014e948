// Ramped tethers to target positions (tether_term.hpp).
#include "protocols/terms/tether_term.hpp"

#include <algorithm>
#include <cmath>

namespace crumple {

TetherTerm::TetherTerm(std::vector<Index> nodes, TargetFn targets, double k_max, double t0,
                       double t_ramp)
    : nodes_(std::move(nodes)), targets_(std::move(targets)), k_max_(k_max), t0_(t0),
      t_ramp_(t_ramp) {}

double TetherTerm::stiffness(double t) const {
  if (t_ramp_ <= 0) return t >= t0_ ? k_max_ : 0.0;
  return k_max_ * std::clamp((t - t0_) / t_ramp_, 0.0, 1.0);
}

const Eigen::Matrix3Xd& TetherTerm::targets_at(double t) const {
  if (!(t == cache_t_)) {
    cache_.resize(3, static_cast<Index>(nodes_.size()));
    targets_(t, cache_);
    cache_t_ = t;
  }
  return cache_;
}

double TetherTerm::energy(const State& s) const {
  const double k = stiffness(s.t);
  const auto& X = targets_at(s.t);
  double e = 0.0;
  for (std::size_t a = 0; a < nodes_.size(); ++a)
    e += 0.5 * k * (node(s.x, nodes_[a]) - X.col(a)).squaredNorm();
  return e;
}

void TetherTerm::add_force(const State& s, VecX& f) const {
  const double k = stiffness(s.t);
  const auto& X = targets_at(s.t);
  for (std::size_t a = 0; a < nodes_.size(); ++a)
    f.segment<3>(3 * nodes_[a]) -= k * (node(s.x, nodes_[a]) - X.col(a));
}

void TetherTerm::add_jacobians(const State& s, Jacobians& J) const {
  const Mat3 K = stiffness(s.t) * Mat3::Identity();
  for (std::size_t a = 0; a < nodes_.size(); ++a) add_block(J.Hx.valuePtr(), slots_[a], K);
}

void TetherTerm::bind(const BlockPattern& p) {
  slots_.resize(nodes_.size());
  for (std::size_t a = 0; a < nodes_.size(); ++a) slots_[a] = p.slot(nodes_[a], nodes_[a]);
}

double TetherTerm::max_deviation(const State& s) const {
  const auto& X = targets_at(s.t);
  double m = 0.0;
  for (std::size_t a = 0; a < nodes_.size(); ++a)
    m = std::max(m, (node(s.x, nodes_[a]) - X.col(a)).norm());
  return m;
}

}  // namespace crumple
