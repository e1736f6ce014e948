// Meshes for the benchmarks: a jittered regular triangulation with about `nodes` nodes on the
// unit square (same node degree and hinge count per node as the Lloyd meshes, and cheap to make).
#pragma once

#include "tests/support/grid_mesh.hpp"

#include <cmath>

namespace crumple {

inline Mesh bench_mesh(int nodes) {
  const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(nodes))));
  return testing::grid_mesh(side, side, 1.0, 1.0, 0.15, 1);
}

}  // namespace crumple
