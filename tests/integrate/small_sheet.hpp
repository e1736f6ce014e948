// The small relaxing sheet of the integrator tests: a jittered 6 x 6 grid, its model constants
// (drag b_iso chosen per test) and start states stretched and bent away from rest.
#pragma once

#include "sim/model/sheet_model.hpp"
#include "tests/support/grid_mesh.hpp"

#include <cmath>

namespace crumple::testing {

inline const Mesh& small_sheet() {
  static const Mesh m = grid_mesh(6, 6, 1.0, 1.0, 0.15, 2);
  return m;
}

inline ModelParams small_sheet_params(double b_iso) {
  ModelParams mp;
  mp.ks = 10;
  mp.kb = 0.01;
  mp.mass = 1;
  mp.b_iso = b_iso;
  return mp;
}

inline State stretched(const SheetModel& model, double factor) {
  State s = model.rest_state();
  s.x *= factor;
  return s;
}

// Stretched by 5 % and bent a little, so that stretching and bending both relax.
inline State stretched_and_bent(const SheetModel& model) {
  State s = stretched(model, 1.05);
  for (Index i = 0; i < model.num_nodes(); ++i) s.x[3 * i + 2] = 0.05 * std::sin(3 * s.x[3 * i]);
  return s;
}

}  // namespace crumple::testing
