// The bend angle of a hinge and its exact first and second derivatives, robust at the flat
// state theta = 0 (docs/MODEL.md §4.3, written here in a per-triangle form).
//
// theta is the signed angle between the normals of T1 = (x0, x1, x2) and T2 = (x1, x0, x3),
// positive when (n1 x n2) . e0 > 0 (paper eq. 14), computed with atan2 so it is accurate over
// the whole range (-pi, pi].
//
// Each triangle of a hinge contributes a "half hinge". For a triangle (p, q, r) whose hinge
// edge runs p -> q and whose third vertex is r, with unit normal n = (q-p) x (r-p) / |.|,
// edge length L, altitude h of r over the edge and tau = (r-p).(q-p)/L^2 the position of the
// foot of r along the edge, the gradient of theta restricted to this triangle is
//     d theta / d x_k = s_k n,   s = ((1 - tau), tau, -1) / h        (k = p, q, r),
// which never divides by sin(theta) and is exact at theta = 0. The Hessian of theta is the sum
// over both half hinges of
//     d^2 theta / dx_k dx_j = s_k r_j n^T + n (grad_j s_k)^T,
// where r_j n^T = d n / d x_j (r_j = n x (opposite edge) / 2A) and grad_j s_k lies in the
// triangle's plane (closed forms in hinge_geometry.cpp). Every expression is checked against
// finite differences in tests/model/test_hinge_geometry.cpp.
#pragma once

#include "sim/core/types.hpp"

namespace crumple {

/// Derivative data of one half hinge; local indices 0, 1, 2 = p, q, r.
struct HalfHinge {
  Vec3 n;                 ///< unit normal of the triangle
  double s[3];            ///< d theta/d x_k = s[k] * n
  Vec3 dn[3];             ///< d n/d x_j = dn[j] * n^T
  Vec3 ds[3][3];          ///< ds[k][j] = gradient of s[k] with respect to x_j (in-plane)
};

/// Computes the half-hinge data of triangle (p, q, r) with hinge edge p -> q.
/// If with_second is false, dn and ds (needed only for the Hessian) are left uninitialised.
void half_hinge(const Vec3& p, const Vec3& q, const Vec3& r, HalfHinge& out, bool with_second);

/// Signed curvature c = 2 sin(theta/2) = sign |n1 - n2| of the hinge, without trigonometry
/// (the quantity the energy and the plastic flow need).
double hinge_curvature(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3);

/// Signed bend angle of the hinge (x0, x1, x2, x3), in (-pi, pi].
double bend_angle(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3);

using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat12 = Eigen::Matrix<double, 12, 12>;

/// Half-angle sines and cosines without trigonometric calls: with unit normals n1, n2,
/// sin(theta/2) = sign |n1 - n2|/2 and cos(theta/2) = |n1 + n2|/2 (docs/MODEL.md §4.1).
struct HalfAngle {
  double sin_half = 0, cos_half = 1;
};

/// theta's half-angle functions, its gradient (12) and optionally its Hessian (12 x 12).
HalfAngle bend_half_angle_derivatives(const Vec3& x0, const Vec3& x1, const Vec3& x2,
                                      const Vec3& x3, Vec12& grad, Mat12* hess);

/// Unit normal n = (x1 - x0) x (x2 - x0) / a2 and twice the area a2 of the triangle (x0, x1, x2).
struct TriangleFrame {
  Vec3 n;
  double a2 = 0;
};
TriangleFrame triangle_frame(const Vec3& x0, const Vec3& x1, const Vec3& x2);

/// The gradient-only bend_half_angle_derivatives from the frames of T1 = (x0, x1, x2) and
/// T2 = (x1, x0, x3), each oriented as written. A mesh's triangle normals can then be computed
/// once per force evaluation rather than once per hinge of the triangle (three for an interior
/// one), and the hinge edge's length once rather than once per wing.
HalfAngle bend_half_angle_gradient(const Vec3& x0, const Vec3& x1, const Vec3& x2,
                                   const Vec3& x3, const TriangleFrame& t1,
                                   const TriangleFrame& t2, Vec12& grad);

/// theta, its gradient (12) and optionally its Hessian (12 x 12) for one hinge.
double bend_angle_derivatives(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3,
                              Vec12& grad, Mat12* hess);

}  // namespace crumple
