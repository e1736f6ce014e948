// Material constants from physical units (units.hpp).
#include "sim/io/units.hpp"

#include <cmath>

namespace crumple {

ResolvedMaterial resolve_material(const MaterialParams& m, double sheet_area, int num_nodes) {
  ResolvedMaterial r;
  if (m.ks > 0) {
    r.model.ks = m.ks;
    r.model.kb = m.kb;
    r.model.mass = m.mass * m.mass_scale;
  } else {
    const double h = m.thickness, nu = m.poisson;
    r.y2d = m.young_modulus * h;
    r.kappa = m.young_modulus * h * h * h / (12.0 * (1.0 - nu * nu));
    r.model.ks = std::sqrt(3.0) / 2.0 * r.y2d;
    r.model.kb = 2.0 * r.kappa / std::sqrt(3.0);
    r.model.mass = m.mass_scale * m.density * h * sheet_area / num_nodes;
  }
  r.y2d = 2.0 * r.model.ks / std::sqrt(3.0);
  r.kappa = std::sqrt(3.0) * r.model.kb / 2.0;
  r.h_eff = std::sqrt(8.0 * r.model.kb / r.model.ks);
  const double scale = std::sqrt(r.model.ks * r.model.mass);
  r.model.b_iso = m.drag_ratio * scale;
  r.model.b_int = m.internal_damping_ratio * scale;
  r.model.area_barrier = m.area_barrier;
  return r;
}

}  // namespace crumple
