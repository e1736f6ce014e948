// Small test meshes that need no mesh generator: a jittered, regularly triangulated rectangle.
#pragma once

#include "sim/mesh/mesh.hpp"

#include <random>

namespace crumple::testing {

/// nx x ny nodes on [0, lx] x [0, ly], interior nodes jittered by up to `jitter` of the spacing,
/// each grid square split along alternating diagonals.
inline Mesh grid_mesh(int nx, int ny, double lx = 1.0, double ly = 1.0, double jitter = 0.15,
                      unsigned seed = 1) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(-jitter, jitter);
  const double dx = lx / (nx - 1), dy = ly / (ny - 1);
  Eigen::Matrix3Xd ref(3, nx * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const bool inner = i > 0 && j > 0 && i < nx - 1 && j < ny - 1;
      ref.col(j * nx + i) = Vec3(i * dx + (inner ? U(rng) * dx : 0.0),
                                 j * dy + (inner ? U(rng) * dy : 0.0), 0.0);
    }
  std::vector<std::array<Index, 3>> tris;
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const Index a = j * nx + i, b = a + 1, c = a + nx, d = c + 1;
      if ((i + j) % 2 == 0) {
        tris.push_back({a, b, d});
        tris.push_back({a, d, c});
      } else {
        tris.push_back({a, b, c});
        tris.push_back({b, d, c});
      }
    }
  return build_mesh(std::move(ref), std::move(tris), "grid");
}

}  // namespace crumple::testing
