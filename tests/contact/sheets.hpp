// Test configurations for contact: grid sheets folded, rolled, crumpled by a smooth random map,
// and two separate layers stacked at a given gap.
#pragma once

#include "tests/support/grid_mesh.hpp"

#include <cmath>
#include <random>

namespace crumple::testing {

/// Hairpin fold about x = fold_x of a sheet lying in the xy plane: the part beyond the fold
/// turns around a half-cylinder of radius gap/2 and comes back at height gap. The map is
/// isometric, so the layers' sites are exactly gap apart where they overlap.
inline VecX fold_sheet(const Mesh& m, double fold_x, double gap) {
  VecX x = m.ref_flat();
  const double R = 0.5 * gap, arc = M_PI * R;
  for (Index i = 0; i < m.num_nodes(); ++i) {
    const double u = m.ref(0, i) - fold_x;
    if (u <= 0) continue;
    if (u < arc) {
      const double phi = u / R;
      x[3 * i] = fold_x + R * std::sin(phi);
      x[3 * i + 2] = R * (1 - std::cos(phi));
    } else {
      x[3 * i] = fold_x - (u - arc);
      x[3 * i + 2] = gap;
    }
  }
  return x;
}

/// Rolls the sheet about an axis parallel to y onto a cylinder of radius R (isometric).
inline VecX roll_sheet(const Mesh& m, double R) {
  VecX x = m.ref_flat();
  for (Index i = 0; i < m.num_nodes(); ++i) {
    const double phi = m.ref(0, i) / R;
    x[3 * i] = R * std::sin(phi);
    x[3 * i + 2] = R * (1 - std::cos(phi));
  }
  return x;
}

/// A smooth random map of the unit-size sheet: a sum of `waves` sine modes of wavelength
/// between size/3 and size, with amplitude `amp` in every component; with amp comparable to the
/// wavelength the sheet wrinkles strongly and comes close to itself in many places.
inline VecX crumple_map(const Mesh& m, unsigned seed, double amp, int waves = 6) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const Vec3 lo = m.ref.rowwise().minCoeff(), hi = m.ref.rowwise().maxCoeff();
  const double size = (hi - lo).maxCoeff();
  struct Wave {
    Vec3 k;
    Vec3 a;
    double phase;
  };
  std::vector<Wave> w;
  for (int q = 0; q < waves; ++q) {
    const double lambda = size * (1.0 / 3.0 + (2.0 / 3.0) * U(rng));
    const double th = 2 * M_PI * U(rng);
    const Vec3 k = (2 * M_PI / lambda) * Vec3(std::cos(th), std::sin(th), 0.0);
    w.push_back({k, amp * Vec3(U(rng) - 0.5, U(rng) - 0.5, 2 * U(rng) - 1), 2 * M_PI * U(rng)});
  }
  VecX x = m.ref_flat();
  for (Index i = 0; i < m.num_nodes(); ++i) {
    const Vec3 p = m.ref.col(i);
    for (const auto& q : w) x.segment<3>(3 * i) += q.a * std::sin(q.k.dot(p) + q.phase);
  }
  return x;
}

/// Two separate n x n grid sheets of side `side` (the second placed beside the first in the
/// reference state so the mesh is a valid flat two-component sheet).
inline Mesh two_sheets(int n, double side, double jitter, unsigned seed) {
  const Mesh a = grid_mesh(n, n, side, side, jitter, seed);
  const Mesh b = grid_mesh(n, n, side, side, jitter, seed + 1);
  const Index na = a.num_nodes();
  Eigen::Matrix3Xd ref(3, na + b.num_nodes());
  ref.leftCols(na) = a.ref;
  ref.rightCols(b.num_nodes()) = b.ref;
  ref.block(0, na, 1, b.num_nodes()).array() += 2 * side;
  std::vector<std::array<Index, 3>> tris = a.triangles;
  for (auto t : b.triangles) tris.push_back({t[0] + na, t[1] + na, t[2] + na});
  return build_mesh(std::move(ref), std::move(tris), "two_sheets");
}

/// Positions of two_sheets(n, ...): the second sheet moved back over the first, at height gap,
/// shifted sideways by `shift` (x, y).
inline VecX stack_sheets(const Mesh& m, double side, double gap, Vec3 shift = Vec3::Zero()) {
  VecX x = m.ref_flat();
  const Index half = m.num_nodes() / 2;
  for (Index i = half; i < m.num_nodes(); ++i) {
    x[3 * i] += -2 * side + shift[0];
    x[3 * i + 1] += shift[1];
    x[3 * i + 2] = gap;
  }
  return x;
}

}  // namespace crumple::testing
