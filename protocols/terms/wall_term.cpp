// One-sided wall potential on every node (wall_term.hpp).
#include "protocols/terms/wall_term.hpp"

#include <cmath>
#include <limits>

namespace crumple {

void WallProfile::eval(double pen, double& U, double& F, double& dF) const {
  if (kind == Kind::Cubic) {
    U = k / 3.0 * pen * pen * pen;
    F = k * pen * pen;
    dF = 2.0 * k * pen;
    return;
  }
  const double e = std::exp(-pen / width), g = 1.0 - e;
  U = f_max * (pen - 2.0 * width * g + 0.5 * width * (1.0 - e * e));
  F = f_max * g * g;
  dF = 2.0 * f_max * g * e / width;
}

WallTerm::WallTerm(std::shared_ptr<const Wall> wall, Index num_nodes, double k, double range)
    : wall_(std::move(wall)), n_(num_nodes), range_(range) {
  profile_.kind = WallProfile::Kind::Cubic;
  profile_.k = k;
}

WallTerm::WallTerm(std::shared_ptr<const Wall> wall, Index num_nodes, WallProfile profile,
                   double range)
    : wall_(std::move(wall)), n_(num_nodes), profile_(profile), range_(range) {}

namespace {
// Node i's penetration of the wall: returns false when out of reach, else fills the profile's
// U, F, dF at the penetration and the distance's gradient (and Hessian if asked for).
struct Contact {
  double U, F, dF;
  Vec3 g;
  Mat3 H;
};
bool touch(const Wall& wall, const WallProfile& prof, double range, const State& s, Index i,
           Contact& c, bool with_hessian = false) {
  double d;
  wall.distance(node(s.x, i), s.t, d, c.g, with_hessian ? &c.H : nullptr);
  if (d >= range) return false;
  prof.eval(range - d, c.U, c.F, c.dF);
  return true;
}
}  // namespace

double WallTerm::energy(const State& s) const {
  double e = 0.0;
#pragma omp parallel for reduction(+ : e) schedule(static)
  for (Index i = 0; i < n_; ++i) {
    Contact c;
    if (touch(*wall_, profile_, range_, s, i, c)) e += c.U;
  }
  return e;
}

void WallTerm::add_force(const State& s, VecX& f) const {
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n_; ++i) {
    Contact c;
    if (touch(*wall_, profile_, range_, s, i, c)) f.segment<3>(3 * i) += c.F * c.g;
  }
}

void WallTerm::add_jacobians(const State& s, Jacobians& J) const {
  double* val = J.Hx.valuePtr();
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n_; ++i) {
    // F = -dU/dd, so Hx = dF/dpen grad d grad d^T - F Hess d.
    Contact c;
    if (touch(*wall_, profile_, range_, s, i, c, true))
      add_block(val, slots_[i], c.dF * c.g * c.g.transpose() - c.F * c.H);
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
    wall_->distance(node(s.x, i), s.t, d, g, nullptr);
    m = std::min(m, d);
  }
  return m;
}

}  // namespace crumple
