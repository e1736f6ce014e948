// The rigid-body part of a velocity field: the translation V and rotation rate w that minimise
//     sum_i |v_i - V - w x (x_i - xc)|^2     (equal node masses, xc the centroid),
// i.e. V = mean v and I w = sum_i r_i x v_i with I = sum_i (|r_i|^2 1 - r_i r_i^T), r_i = x_i - xc
// (the least-squares, or Tisserand, frame of a deformable body). Quiescence tests use what is
// left: a free sheet that drifts or spins slowly is at rest in its shape.
#pragma once

#include "sim/core/types.hpp"

namespace crumple {

struct RigidMotion {
  Vec3 centroid = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();  ///< V, of the centroid
  Vec3 omega = Vec3::Zero();     ///< w
};

/// x, v: 3n (node-major). A degenerate inertia (all nodes on a line) drops the unresolved
/// rotation components (pseudo-inverse).
RigidMotion best_fit_rigid_motion(const VecX& x, const VecX& v);
/// max_i |v_i - V - w x (x_i - xc)|.
double max_speed_relative_to_rigid(const VecX& x, const VecX& v);

}  // namespace crumple
