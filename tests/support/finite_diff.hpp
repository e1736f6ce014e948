// The one finite-difference checker applied to every force term (docs/MODEL.md §2).
//
// For a ForceTerm at a state it compares, by central differences with step h:
//   - the force against minus the gradient of the energy (conservative terms only),
//   - Hx against -dF/dx, Hv against -dF/dv and Hp against -dF/dp, column by column,
// and reports relative errors |A - A_fd|_F / |A_fd|_F and the asymmetry of Hx.
#pragma once

#include "sim/model/force_term.hpp"

#include <Eigen/Dense>
#include <algorithm>

namespace crumple::testing {

struct FdReport {
  double force = 0;  ///< relative error of F vs -grad E (0 for dissipative terms)
  double hx = 0, hv = 0, hp = 0;
  double hx_asymmetry = 0;  ///< |Hx - Hx^T|_F / |Hx|_F
  double force_norm = 0, hx_norm = 0, hv_norm = 0, hp_norm = 0;
};

inline double rel_err(const Eigen::MatrixXd& a, const Eigen::MatrixXd& ref) {
  const double scale = std::max(ref.norm(), 1e-300);
  return (a - ref).norm() / scale;
}

/// h is the absolute step on x, v and p.
inline FdReport check_term(ForceTerm& term, const State& s0, Index num_hinges, double h = 1e-6) {
  const Index dofs = static_cast<Index>(s0.x.size());
  const Index nodes = dofs / 3;
  std::vector<std::pair<Index, Index>> pairs;
  term.coupled_pairs(pairs);
  BlockPattern pattern(nodes, pairs);
  term.bind(pattern);

  Jacobians J;
  J.reset(pattern);
  J.Hp = SpMatCol(dofs, num_hinges);
  term.add_jacobians(s0, J);
  const Eigen::MatrixXd Hx(J.Hx), Hv(J.Hv), Hp(J.Hp);

  auto force = [&](const State& s) {
    VecX f = VecX::Zero(dofs);
    term.add_force(s, f);
    return f;
  };
  const VecX f0 = force(s0);

  FdReport r;
  Eigen::MatrixXd Hx_fd(dofs, dofs), Hv_fd(dofs, dofs), Hp_fd(dofs, num_hinges);
  VecX grad_fd(dofs);
  for (Index k = 0; k < dofs; ++k) {
    State a = s0, b = s0;
    a.x[k] += h;
    b.x[k] -= h;
    Hx_fd.col(k) = -(force(a) - force(b)) / (2 * h);
    if (term.conservative()) grad_fd[k] = (term.energy(a) - term.energy(b)) / (2 * h);
    State c = s0, d = s0;
    c.v[k] += h;
    d.v[k] -= h;
    Hv_fd.col(k) = -(force(c) - force(d)) / (2 * h);
  }
  for (Index k = 0; k < num_hinges; ++k) {
    State a = s0, b = s0;
    a.p[k] += h;
    b.p[k] -= h;
    Hp_fd.col(k) = -(force(a) - force(b)) / (2 * h);
  }
  // A force that vanishes (a spring at rest length) is compared on the scale of the force that
  // a displacement of 1e-8 (relative to unit length) would cause.
  if (term.conservative())
    r.force = (f0 + grad_fd).norm() / std::max(grad_fd.norm(), 1e-6 * Hx.norm());
  r.hx = rel_err(Hx, Hx_fd);
  r.hv = Hv_fd.norm() > 0 ? rel_err(Hv, Hv_fd) : Hv.norm();
  r.hp = Hp_fd.norm() > 0 ? rel_err(Hp, Hp_fd) : Hp.norm();
  r.hx_asymmetry = Hx.norm() > 0 ? (Hx - Hx.transpose()).norm() / Hx.norm() : 0.0;
  r.force_norm = f0.norm();
  r.hx_norm = Hx.norm();
  r.hv_norm = Hv.norm();
  r.hp_norm = Hp.norm();
  return r;
}

}  // namespace crumple::testing
