// The fold angle of a sheet folded about the line x = 0 of its reference frame (the `fold`
// stage's default line): the angle theta_f between the mean normals of the two flaps, the
// triangles farther than `margin` from the line (paper Fig. 3b: theta_f = pi - phi_f, phi_f the
// angle between the flaps' planes; 0 for a flat sheet, pi for one folded flat).
#pragma once

#include "sim/mesh/mesh.hpp"
#include "sim/model/state.hpp"

#include <algorithm>
#include <cmath>

namespace crumple::testing {

inline double flap_angle(const Mesh& m, const State& s, double margin) {
  Vec3 n1 = Vec3::Zero(), n2 = Vec3::Zero();
  for (const auto& t : m.triangles) {
    const double cx = (m.ref(0, t[0]) + m.ref(0, t[1]) + m.ref(0, t[2])) / 3.0;
    const Vec3 a = node(s.x, t[0]), b = node(s.x, t[1]), c = node(s.x, t[2]);
    const Vec3 n = (b - a).cross(c - a);  // area-weighted
    if (cx < -margin) n1 += n;
    if (cx > margin) n2 += n;
  }
  return std::acos(std::clamp(n1.normalized().dot(n2.normalized()), -1.0, 1.0));
}

}  // namespace crumple::testing
