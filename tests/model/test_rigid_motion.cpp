// The best-fit rigid motion of a velocity field (sim/model/rigid_motion.hpp): a rigid field is
// recovered exactly and leaves no deformation speed; a deformation orthogonal to the rigid
// motions is left whole; a field on a line (degenerate inertia) does not blow up.
#include "sim/model/rigid_motion.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace crumple;

namespace {

VecX random_points(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  VecX x(3 * n);
  for (auto& v : x) v = U(rng);
  return x;
}

VecX rigid_field(const VecX& x, const Vec3& V, const Vec3& w, const Vec3& about) {
  VecX v(x.size());
  for (Index i = 0; i < x.size() / 3; ++i) node(v, i) = V + w.cross(node(x, i) - about);
  return v;
}

}  // namespace

TEST(RigidMotion, RecoversARigidField) {
  const VecX x = random_points(200, 1);
  const Vec3 V(0.3, -0.2, 0.1), w(1.5, 0.4, -2.0);
  const VecX v = rigid_field(x, V, w, Vec3(0.5, 0.5, 0.0));
  const RigidMotion m = best_fit_rigid_motion(x, v);
  EXPECT_LT((m.omega - w).norm(), 1e-12);
  // V is the centroid's velocity: the field evaluated at the centroid.
  EXPECT_LT((m.velocity - (V + w.cross(m.centroid - Vec3(0.5, 0.5, 0.0)))).norm(), 1e-12);
  EXPECT_LT(max_speed_relative_to_rigid(x, v), 1e-12);
}

TEST(RigidMotion, LeavesTheDeformationOfAFlatSheet) {
  // A flat sheet (z = 0) drifting and spinning about z while it flaps: v_z = a (x^2 - <x^2>)
  // has no linear part in x, y, so no rigid motion absorbs any of it.
  const int n = 21;
  VecX x(3 * n * n);
  double mean_x2 = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = -1.0 + 2.0 * i / (n - 1), y = -1.0 + 2.0 * j / (n - 1);
      node(x, j * n + i) = Vec3(u, y, 0.0);
      mean_x2 += u * u / (n * n);
    }
  const double a = 0.01;
  VecX flap = VecX::Zero(x.size());
  double max_flap = 0;
  for (Index k = 0; k < n * n; ++k) {
    flap[3 * k + 2] = a * (x[3 * k] * x[3 * k] - mean_x2);
    max_flap = std::max(max_flap, std::abs(flap[3 * k + 2]));
  }
  const VecX v = rigid_field(x, Vec3(2.0, 1.0, -0.5), Vec3(0.0, 0.0, 3.0), Vec3::Zero()) + flap;
  EXPECT_NEAR(max_speed_relative_to_rigid(x, v), max_flap, 1e-12);
  // Without removing the rigid motion the drift dominates by orders of magnitude.
  EXPECT_GT(v.segment<3>(0).norm(), 100 * max_flap);
}

TEST(RigidMotion, CollinearNodesDoNotBlowUp) {
  VecX x(3 * 5);
  for (int i = 0; i < 5; ++i) node(x, i) = Vec3(i, 0, 0);
  const VecX v = rigid_field(x, Vec3(1, 0, 0), Vec3(0, 0, 2), Vec3::Zero());
  const RigidMotion m = best_fit_rigid_motion(x, v);
  EXPECT_TRUE(m.omega.allFinite());
  EXPECT_LT(max_speed_relative_to_rigid(x, v), 1e-12);
}
