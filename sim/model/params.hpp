// Constants of the sheet model in simulation units (paper Table 1).
#pragma once

namespace crumple {

struct ModelParams {
  double ks = 1.0;     ///< spring constant (3), M/T^2
  double kb = 1.0;     ///< bending constant (15), M L^2/T^2
  double mass = 1.0;   ///< mass per node, M
  double b_iso = 0.0;  ///< isotropic drag (8), M/T
  double b_int = 0.0;  ///< internal (dashpot) damping (9), M/T
  bool area_barrier = true;  ///< keep triangles from collapsing (area_barrier.hpp)
};

}  // namespace crumple
