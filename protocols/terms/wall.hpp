// Rigid walls as smooth one-sided repulsive potentials (docs/MODEL.md §11.2): plane, cylinder,
// sphere, cone. A wall is a signed distance d(x, t) to its surface, positive on the allowed side; each
// node with d < range feels the potential
//     U(d) = k/3 (range - d)^3,   F = -U'(d) grad d = k (range - d)^2 grad d,
// which is C^2 at d = range (no kink for the adaptive integrators) and stiffens as a node
// penetrates. Hx = U''(d) grad d grad d^T + U'(d) Hess d, with U'' = 2k(range - d).
// Surfaces may move (pistons, shrinking radii): their geometry is a function of time.
#pragma once

#include "sim/core/types.hpp"

#include <functional>
#include <limits>
#include <memory>
#include <string>

namespace crumple {

/// Signed distance of a surface and its derivatives, positive on the allowed side.
class Wall {
 public:
  virtual ~Wall() = default;
  virtual std::string name() const = 0;
  /// d, grad d and, when hess is not null, Hess d at x and time t (forces and energies need
  /// no Hessian, and building it for every node was a measurable part of an explicit step).
  virtual void distance(const Vec3& x, double t, double& d, Vec3& grad, Mat3* hess) const = 0;
};

/// A quantity that moves linearly in time from v0 at t0 with rate `speed`, clamped at `target`
/// once reached (pistons moving to a target position, radii shrinking to a final value).
struct LinearMotion {
  double v0 = 0, speed = 0, t0 = 0;
  double target = std::numeric_limits<double>::quiet_NaN();  ///< NaN: no clamp
  double at(double t) const;
};

/// Half-space {(x - point) . normal >= 0}; the point moves along the normal by `offset`.
class PlaneWall : public Wall {
 public:
  PlaneWall(const Vec3& point, const Vec3& normal, LinearMotion offset = {});
  std::string name() const override { return "plane"; }
  void distance(const Vec3& x, double t, double& d, Vec3& g, Mat3* H) const override;
  double offset(double t) const { return offset_.at(t); }

 private:
  Vec3 p_, n_;
  LinearMotion offset_;
};

/// Infinite cylinder about the axis through `point` along `axis`; allowed region inside
/// (a container) or outside (a mandrel).
class CylinderWall : public Wall {
 public:
  CylinderWall(const Vec3& point, const Vec3& axis, LinearMotion radius, bool inside);
  std::string name() const override { return "cylinder"; }
  void distance(const Vec3& x, double t, double& d, Vec3& g, Mat3* H) const override;
  double radius(double t) const { return radius_.at(t); }

 private:
  Vec3 c_, a_;
  LinearMotion radius_;
  double sign_;
};

/// Sphere about `center`; allowed region inside or outside. With a shrinking radius and a soft
/// stiffness this is the radial cutoff force of the paper's radial confinement (Fig. 5). The
/// centre may move along `direction` by `offset` (a stamp pressed into the sheet).
class SphereWall : public Wall {
 public:
  SphereWall(const Vec3& center, LinearMotion radius, bool inside,
             const Vec3& direction = Vec3::UnitZ(), LinearMotion offset = {});
  std::string name() const override { return "sphere"; }
  void distance(const Vec3& x, double t, double& d, Vec3& g, Mat3* H) const override;
  double radius(double t) const { return radius_.at(t); }

 private:
  Vec3 c_, dir_;
  LinearMotion radius_;
  double sign_;
  LinearMotion offset_;
};

/// Cone with apex `apex`, unit `axis` and half-angle alpha (radians); allowed region inside or
/// outside the cone surface. The apex moves along the axis by `offset` (pulling a sheet
/// through a conical funnel). The distance is exact wherever the nearest surface point is not
/// the apex.
class ConeWall : public Wall {
 public:
  ConeWall(const Vec3& apex, const Vec3& axis, double half_angle, bool inside,
           LinearMotion offset = {});
  std::string name() const override { return "cone"; }
  void distance(const Vec3& x, double t, double& d, Vec3& g, Mat3* H) const override;

 private:
  Vec3 apex_, a_;
  double cos_, sin_, sign_;
  LinearMotion offset_;
};

}  // namespace crumple
