// The pairwise contact law between two contact sites (paper eq. 10-12, Appendix B.3 B.8-B.10).
//
// For sites at x1, x2 with r = x1 - x2, d = |r| and rho = sigma / (d - sigma) (so rho runs from
// -1 at d = 0 to -infinity at d = sigma), the force on site 1 is (eq. 10, B.9)
//     F1 = ks (sigma/d) rho^2 e^rho r   for d < sigma,   0 beyond,
// a repulsion of magnitude f(d) = ks sigma rho^2 e^rho. Since d(e^rho)/dd = -e^rho rho^2/sigma,
// f = -ks sigma^2 d(e^rho)/dd, so F1 = -dE/dr with the closed-form energy
//     E(d) = ks sigma^2 e^rho = ks sigma^2 exp(sigma / (d - sigma)),
// which is bounded (E(0) = ks sigma^2 / e) and vanishes with all its derivatives at d = sigma
// (every derivative is a polynomial in rho times e^rho): the force is C-infinity across the
// range, which is what keeps adaptive step control happy when pairs enter or leave it.
// The stiffness block is
//     K = -dF1/dr = (ks sigma/d) rho^2 e^rho [ -I + (rho^2 + 2 rho + sigma/d) r r^T / (sigma d) ],
// the bracket of B.10. Note the sign: on the nodes, Hx = -dF/dx gives +w_a w_b K between two
// nodes of the same site and -w_a w_m K across the pair (B.10 prints the cross block with the
// same-site sign; the finite-difference tests fix the convention used here).
// The force on node a of either site is c_a F1 with c_a = +w_a on site 1 and -w_a on site 2
// (eq. 11-12), and Hx_ab = c_a c_b K; forces sum to zero and, because F1 is parallel to r,
// exert no net torque.
#pragma once

#include "sim/core/types.hpp"

#include <cmath>

namespace crumple {

struct ContactLaw {
  double ks = 1.0;     ///< stiffness (the spring constant ks of eq. 3 in the paper), M/T^2
  double sigma = 1.0;  ///< interaction range, L (paper: the effective thickness h_eff)

  /// rho = sigma/(d - sigma) for d < sigma. Below rho = -700 every term of the law is below
  /// 1e-300 of its scale; report "out of range" there so rho^2 e^rho never meets inf * 0.
  bool in_range(double d, double& rho) const {
    if (d >= sigma) return false;
    rho = sigma / (d - sigma);
    return rho > -700.0;
  }

  /// E(d) = ks sigma^2 exp(rho), zero for d >= sigma.
  double energy(double d) const {
    double rho;
    return in_range(d, rho) ? ks * sigma * sigma * std::exp(rho) : 0.0;
  }

  /// Radial force magnitude f(d) = -E'(d) = ks sigma rho^2 e^rho (>= 0: repulsive).
  double magnitude(double d) const {
    double rho;
    return in_range(d, rho) ? ks * sigma * rho * rho * std::exp(rho) : 0.0;
  }

  /// F1(r) on site 1 (eq. 10). Coincident sites (d = 0) have no direction and get no force.
  Vec3 force(const Vec3& r) const {
    const double d = r.norm();
    double rho;
    if (d <= 0.0 || !in_range(d, rho)) return Vec3::Zero();
    return (ks * sigma * rho * rho * std::exp(rho) / d) * r;
  }

  /// K = -dF1/dr (symmetric, 3x3; B.10's bracket). Zero outside the range and at d = 0.
  Mat3 stiffness(const Vec3& r) const {
    const double d = r.norm();
    double rho;
    if (d <= 0.0 || !in_range(d, rho)) return Mat3::Zero();
    const double g = ks * sigma * rho * rho * std::exp(rho) / d;
    const double c = (rho * rho + 2.0 * rho + sigma / d) / (sigma * d);
    return g * (c * (r * r.transpose()) - Mat3::Identity());
  }
};

}  // namespace crumple
