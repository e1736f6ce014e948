// From the material section to model constants (paper eq. 5-7, Appendix A):
//   Y2D = Y h,  kappa = Y h^3 / (12 (1 - nu^2)),  ks = (sqrt(3)/2) Y2D,  kb = 2 kappa / sqrt(3),
// so that h_eff = sqrt(8 kb / ks) equals h; node mass m = mass_scale density h A / n; drag and
// internal damping b = ratio sqrt(ks m). Or ks, kb, m given directly.
#pragma once

#include "sim/io/params.hpp"
#include "sim/model/params.hpp"

namespace crumple {

struct ResolvedMaterial {
  ModelParams model;
  double h_eff = 0, kappa = 0, y2d = 0;
};

ResolvedMaterial resolve_material(const MaterialParams& m, double sheet_area, int num_nodes);

}  // namespace crumple
