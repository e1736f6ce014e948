// The dynamical state of a sheet: positions x, velocities v (both 3n, flat), plastic rest
// curvature p (one per hinge, paper eq. 15-18) and the simulated time t.
#pragma once

#include "sim/core/types.hpp"

namespace crumple {

struct State {
  VecX x;        ///< 3n node positions
  VecX v;        ///< 3n node velocities
  VecX p;        ///< per hinge: signed plastic rest curvature 2 sin(theta_bar/2), in [-2, 2]
  double t = 0;  ///< simulated time
};

}  // namespace crumple
