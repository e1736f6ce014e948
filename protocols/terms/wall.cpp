// Signed distances of the rigid walls and their derivatives (wall.hpp).
#include "protocols/terms/wall.hpp"

#include <cmath>

namespace crumple {

double LinearMotion::at(double t) const {
  const double v = v0 + speed * (t - t0);
  if (std::isnan(target)) return v;
  return speed >= 0 ? std::min(v, target) : std::max(v, target);
}

PlaneWall::PlaneWall(const Vec3& point, const Vec3& normal, LinearMotion offset)
    : p_(point), n_(normal.normalized()), offset_(offset) {}

void PlaneWall::distance(const Vec3& x, double t, double& d, Vec3& g, Mat3* H) const {
  d = (x - p_).dot(n_) - offset_.at(t);
  g = n_;
  if (H) H->setZero();
}

CylinderWall::CylinderWall(const Vec3& point, const Vec3& axis, LinearMotion radius, bool inside)
    : c_(point), a_(axis.normalized()), radius_(radius), sign_(inside ? 1.0 : -1.0) {}

void CylinderWall::distance(const Vec3& x, double t, double& d, Vec3& g, Mat3* H) const {
  const Vec3 r = x - c_;
  const Vec3 q = r - r.dot(a_) * a_;  // radial part
  const double rho = std::max(q.norm(), 1e-300);
  const Vec3 u = q / rho;
  // d(rho) = u, Hess(rho) = (P - u u^T)/rho with P the projector across the axis.
  d = sign_ * (radius_.at(t) - rho);
  g = -sign_ * u;
  if (H) *H = -sign_ * (Mat3::Identity() - a_ * a_.transpose() - u * u.transpose()) / rho;
}

SphereWall::SphereWall(const Vec3& center, LinearMotion radius, bool inside,
                       const Vec3& direction, LinearMotion offset)
    : c_(center), dir_(direction.normalized()), radius_(radius), sign_(inside ? 1.0 : -1.0),
      offset_(offset) {}

void SphereWall::distance(const Vec3& x, double t, double& d, Vec3& g, Mat3* H) const {
  const Vec3 r = x - (c_ + offset_.at(t) * dir_);
  const double l = std::max(r.norm(), 1e-300);
  const Vec3 u = r / l;
  d = sign_ * (radius_.at(t) - l);
  g = -sign_ * u;
  if (H) *H = -sign_ * (Mat3::Identity() - u * u.transpose()) / l;
}

ConeWall::ConeWall(const Vec3& apex, const Vec3& axis, double half_angle, bool inside,
                   LinearMotion offset)
    : apex_(apex),
      a_(axis.normalized()),
      cos_(std::cos(half_angle)),
      sin_(std::sin(half_angle)),
      sign_(inside ? 1.0 : -1.0),
      offset_(offset) {}

void ConeWall::distance(const Vec3& x, double t, double& d, Vec3& g, Mat3* H) const {
  // Distance to the cone surface, positive inside: h sin(alpha) - rho cos(alpha), with h the
  // height along the axis and rho the distance from the axis.
  const Vec3 r = x - (apex_ + offset_.at(t) * a_);
  const double h = r.dot(a_);
  const Vec3 q = r - h * a_;
  const double rho = std::max(q.norm(), 1e-300);
  const Vec3 u = q / rho;
  d = sign_ * (h * sin_ - rho * cos_);
  g = sign_ * (sin_ * a_ - cos_ * u);
  if (H) *H = -sign_ * cos_ * (Mat3::Identity() - a_ * a_.transpose() - u * u.transpose()) / rho;
}

}  // namespace crumple
