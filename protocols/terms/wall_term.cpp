// One-sided wall potential on every node (wall_term.hpp).
#include "protocols/terms/wall_term.hpp"

#include <limits>

namespace crumple {

WallTerm::WallTerm(std::shared_ptr<const Wall> wall, Index num_nodes, double k, double range)
    : wall_(std::move(wall)), n_(num_nodes), k_(k), range_(range) {}

double WallTerm::energy(const State& s) const {
  double e = 0.0;
#pragma omp parallel for reduction(+ : e) schedule(static)
  for (Index i = 0; i < n_; ++i) {
    double d;
    Vec3 g;
    Mat3 H;
    wall_->distance(node(s.x, i), s.t, d, g, H);
    if (d < range_) {
      const double pen = range_ - d;
      e += k_ / 3.0 * pen * pen * pen;
    }
  }
  return e;
}

void WallTerm::add_force(const State& s, VecX& f) const {
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n_; ++i) {
    double d;
    Vec3 g;
    Mat3 H;
    wall_->distance(node(s.x, i), s.t, d, g, H);
    if (d < range_) {
      const double pen = range_ - d;
      f.segment<3>(3 * i) += (k_ * pen * pen) * g;
    }
  }
}

void WallTerm::add_jacobians(const State& s, Jacobians& J) const {
  double* val = J.Hx.valuePtr();
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n_; ++i) {
    double d;
    Vec3 g;
    Mat3 H;
    wall_->distance(node(s.x, i), s.t, d, g, H);
    if (d < range_) {
      const double pen = range_ - d;
      // U' = -k pen^2, U'' = 2 k pen.
      add_block(val, slots_[i], (2.0 * k_ * pen) * g * g.transpose() - (k_ * pen * pen) * H);
    }
  }
}

void WallTerm::bind(const BlockPattern& p) {
  slots_.resize(n_);
  for (Index i = 0; i < n_; ++i) slots_[i] = p.slot(i, i);
}

Vec3 WallTerm::reaction(const State& s) const {
  VecX f = VecX::Zero(3 * n_);
  add_force(s, f);
  Vec3 r = Vec3::Zero();
  for (Index i = 0; i < n_; ++i) r -= node(f, i);
  return r;
}

double WallTerm::min_distance(const State& s) const {
  double m = std::numeric_limits<double>::infinity();
  for (Index i = 0; i < n_; ++i) {
    double d;
    Vec3 g;
    Mat3 H;
    wall_->distance(node(s.x, i), s.t, d, g, H);
    m = std::min(m, d);
  }
  return m;
}

}  // namespace crumple
