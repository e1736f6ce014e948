// Bend angle and its derivatives (hinge_geometry.hpp).
//
// Derivation of the in-plane gradients of s (see the header for the notation). With the
// right-handed frame (e, m, n) of the triangle, e = (q-p)/L and m = n x e pointing from the edge
// towards r, the foot parameter and the altitude vary as
//   d tau/d p = (tau-1) e/L - h m/L^2,   d tau/d q = -tau e/L + h m/L^2,   d tau/d r = e/L,
//   d h/d p   = -(1-tau) m,              d h/d q   = -tau m,               d h/d r   = m,
// (moving p or q tilts the edge line; only in-plane motion matters to first order), and
// s_p = (1-tau)/h, s_q = tau/h, s_r = -1/h follow by the quotient rule.
#include "sim/model/hinge_geometry.hpp"

#include <cmath>

namespace crumple {

namespace {
// The first-order quantities of a half hinge (p, q, r): edge e = q - p, unit normal, twice the
// area, edge length, altitude of r and foot parameter tau. Returned by value so that the
// gradient-only path keeps them in registers.
struct Wing {
  Vec3 e, n;
  double a2, l2, l, h, tau;
};

inline Wing wing(const Vec3& p, const Vec3& q, const Vec3& r) {
  Wing w;
  w.e = q - p;
  const Vec3 pr = r - p;
  const Vec3 nv = w.e.cross(pr);
  w.a2 = nv.norm();
  w.l2 = w.e.squaredNorm();
  w.l = std::sqrt(w.l2);
  w.n = nv / w.a2;
  w.h = w.a2 / w.l;
  w.tau = pr.dot(w.e) / w.l2;
  return w;
}

// Half-angle sine and cosine from the two unit normals (x1 - x0 is the hinge edge).
inline HalfAngle half_angle(const Vec3& n1, const Vec3& n2, const Vec3& e0) {
  HalfAngle h;
  const double sign = n1.cross(n2).dot(e0) < 0 ? -1.0 : 1.0;
  h.sin_half = 0.5 * sign * (n1 - n2).norm();
  h.cos_half = 0.5 * (n1 + n2).norm();
  return h;
}
}  // namespace

void half_hinge(const Vec3& p, const Vec3& q, const Vec3& r, HalfHinge& o, bool with_second) {
  const auto [e, n, a2, l2, l, h, tau] = wing(p, q, r);
  o.n = n;
  o.s[0] = (1.0 - tau) / h;
  o.s[1] = tau / h;
  o.s[2] = -1.0 / h;
  if (!with_second) return;
  o.dn[0] = o.n.cross(q - r) / a2;
  o.dn[1] = o.n.cross(r - p) / a2;
  o.dn[2] = o.n.cross(p - q) / a2;

  const Vec3 eh = e / l;
  const Vec3 m = o.n.cross(eh);
  const double lh = 1.0 / (l * h), il2 = 1.0 / l2, ih2 = 1.0 / (h * h);
  const double u = 1.0 - tau;
  o.ds[0][0] = (u * lh) * eh + (il2 + u * u * ih2) * m;
  o.ds[0][1] = (tau * lh) * eh + (-il2 + tau * u * ih2) * m;
  o.ds[0][2] = (-lh) * eh - (u * ih2) * m;
  o.ds[1][0] = (-u * lh) * eh + (-il2 + tau * u * ih2) * m;
  o.ds[1][1] = (-tau * lh) * eh + (il2 + tau * tau * ih2) * m;
  o.ds[1][2] = lh * eh - (tau * ih2) * m;
  o.ds[2][0] = -(u * ih2) * m;
  o.ds[2][1] = -(tau * ih2) * m;
  o.ds[2][2] = ih2 * m;
}

double hinge_curvature(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  const Vec3 e0 = x1 - x0;
  const Vec3 n1 = e0.cross(x2 - x0).normalized();
  const Vec3 n2 = (x3 - x0).cross(e0).normalized();
  const double c = (n1 - n2).norm();
  return n1.cross(n2).dot(e0) < 0 ? -c : c;
}

double bend_angle(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  const Vec3 e0 = x1 - x0;
  const Vec3 n1 = e0.cross(x2 - x0).normalized();
  const Vec3 n2 = (x3 - x0).cross(e0).normalized();
  return std::atan2(n1.cross(n2).dot(e0.normalized()), n1.dot(n2));
}

namespace {
void assemble_hinge(const HalfHinge& t1, const HalfHinge& t2, Vec12& grad, Mat12* hess) {
  static constexpr int map1[3] = {0, 1, 2};
  static constexpr int map2[3] = {1, 0, 3};
  grad.setZero();
  for (int k = 0; k < 3; ++k) {
    grad.segment<3>(3 * map1[k]) += t1.s[k] * t1.n;
    grad.segment<3>(3 * map2[k]) += t2.s[k] * t2.n;
  }
  if (hess) {
    hess->setZero();
    for (const auto& [t, map] : {std::pair{&t1, map1}, std::pair{&t2, map2}})
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
          hess->block<3, 3>(3 * map[k], 3 * map[j]) +=
              t->s[k] * t->dn[j] * t->n.transpose() + t->n * t->ds[k][j].transpose();
  }
}
}  // namespace

HalfAngle bend_half_angle_derivatives(const Vec3& x0, const Vec3& x1, const Vec3& x2,
                                      const Vec3& x3, Vec12& grad, Mat12* hess) {
  if (!hess) {
    // The gradient alone (every force evaluation): s_k n of both wings written straight into
    // grad, without the HalfHinge round trip through memory that assemble_hinge needs (a
    // profile of explicit steps had 15 % of the time in that copy).
    const Wing a = wing(x0, x1, x2), b = wing(x1, x0, x3);  // T2 = (x1, x0, x3)
    const double ia = 1.0 / a.h, ib = 1.0 / b.h;
    grad.segment<3>(0) = ((1.0 - a.tau) * ia) * a.n + (b.tau * ib) * b.n;
    grad.segment<3>(3) = (a.tau * ia) * a.n + ((1.0 - b.tau) * ib) * b.n;
    grad.segment<3>(6) = -ia * a.n;
    grad.segment<3>(9) = -ib * b.n;
    return half_angle(a.n, b.n, a.e);
  }
  HalfHinge t1, t2;
  half_hinge(x0, x1, x2, t1, true);  // local (0,1,2) -> hinge (0,1,2)
  half_hinge(x1, x0, x3, t2, true);  // local (0,1,2) -> hinge (1,0,3)
  assemble_hinge(t1, t2, grad, hess);
  return half_angle(t1.n, t2.n, x1 - x0);
}

TriangleFrame triangle_frame(const Vec3& x0, const Vec3& x1, const Vec3& x2) {
  TriangleFrame f;
  const Vec3 nv = (x1 - x0).cross(x2 - x0);
  f.a2 = nv.norm();
  f.n = nv / f.a2;
  return f;
}

HalfAngle bend_half_angle_gradient(const Vec3& x0, const Vec3& x1, const Vec3& x2,
                                   const Vec3& x3, const TriangleFrame& t1,
                                   const TriangleFrame& t2, Vec12& grad) {
  // The wings of the gradient-only path above with n and h = a2 / L taken from the frames;
  // T2's edge is x0 - x1, so its foot parameter is (x3 - x1).(x0 - x1) / L^2.
  const Vec3 e = x1 - x0;
  const double l2 = e.squaredNorm(), l = std::sqrt(l2), il2 = 1.0 / l2;
  const double ta = (x2 - x0).dot(e) * il2, tb = (x1 - x3).dot(e) * il2;
  const double ia = l / t1.a2, ib = l / t2.a2;  // 1 / h of each wing
  grad.segment<3>(0) = ((1.0 - ta) * ia) * t1.n + (tb * ib) * t2.n;
  grad.segment<3>(3) = (ta * ia) * t1.n + ((1.0 - tb) * ib) * t2.n;
  grad.segment<3>(6) = -ia * t1.n;
  grad.segment<3>(9) = -ib * t2.n;
  return half_angle(t1.n, t2.n, e);
}

double bend_angle_derivatives(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3,
                              Vec12& grad, Mat12* hess) {
  HalfHinge t1, t2;
  half_hinge(x0, x1, x2, t1, hess != nullptr);
  half_hinge(x1, x0, x3, t2, hess != nullptr);
  assemble_hinge(t1, t2, grad, hess);
  const Vec3 e0 = x1 - x0;
  return std::atan2(t1.n.cross(t2.n).dot(e0.normalized()), t1.n.dot(t2.n));
}

}  // namespace crumple
