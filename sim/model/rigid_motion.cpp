// Best-fit rigid motion of a velocity field (rigid_motion.hpp).
#include "sim/model/rigid_motion.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace crumple {

RigidMotion best_fit_rigid_motion(const VecX& x, const VecX& v) {
  RigidMotion m;
  const Index n = x.size() / 3;
  if (n == 0) return m;
  for (Index i = 0; i < n; ++i) m.centroid += node(x, i), m.velocity += node(v, i);
  m.centroid /= static_cast<double>(n);
  m.velocity /= static_cast<double>(n);
  Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
  Vec3 L = Vec3::Zero();
  for (Index i = 0; i < n; ++i) {
    const Vec3 r = node(x, i) - m.centroid;
    I += r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose();
    L += r.cross(node(v, i) - m.velocity);
  }
  // I is symmetric positive semi-definite; invert on its resolved eigenvalues only.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(I);
  const Vec3 lam = es.eigenvalues();
  const double cut = 1e-12 * std::max(lam.maxCoeff(), 1e-300);
  Vec3 y = es.eigenvectors().transpose() * L;
  for (int k = 0; k < 3; ++k) y[k] = lam[k] > cut ? y[k] / lam[k] : 0.0;
  m.omega = es.eigenvectors() * y;
  return m;
}

double max_speed_relative_to_rigid(const VecX& x, const VecX& v) {
  const RigidMotion m = best_fit_rigid_motion(x, v);
  double s = 0;
  for (Index i = 0; i < x.size() / 3; ++i) {
    const Vec3 u = node(v, i) - m.velocity - m.omega.cross(node(x, i) - m.centroid);
    s = std::max(s, u.norm());
  }
  return s;
}

}  // namespace crumple
