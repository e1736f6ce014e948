// The apparatus's restart entries (apparatus.hpp).
#include "protocols/apparatus.hpp"

namespace crumple {

void save_restart(const Apparatus& a, RestartData& out) {
  out.ints["rolled"] = a.rolled;
  out.arrays["axis"] = {a.axis_point.x(), a.axis_point.y(), a.axis_point.z(), a.axis_dir.x(),
                        a.axis_dir.y(),   a.axis_dir.z(),   a.radius,         a.height};
}

Apparatus load_apparatus(const RestartData& in) {
  Apparatus a;
  a.rolled = in.integer("rolled") != 0;
  const std::vector<double>& v = in.array("axis");
  if (v.size() != 8) in.fail("/axis", "expected 8 values");
  a.axis_point = Vec3(v[0], v[1], v[2]);
  a.axis_dir = Vec3(v[3], v[4], v[5]);
  a.radius = v[6];
  a.height = v[7];
  return a;
}

}  // namespace crumple
