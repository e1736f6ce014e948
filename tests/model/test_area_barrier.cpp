// The area barrier (sim/model/area_barrier.hpp): silent while every triangle keeps more than
// half its rest area, then a force that opens a triangle being pressed flat, with exact
// derivatives (finite differences) down to and at zero area, no net force or torque, and an
// energy that grows steeply, to a finite value, as the triangle collapses.
#include "sim/model/area_barrier.hpp"
#include "sim/model/sheet_model.hpp"
#include "tests/support/finite_diff.hpp"
#include "tests/support/grid_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace crumple;
using namespace crumple::testing;

namespace {

// One triangle: base (0,0,0)-(1,0,0), apex (0.4, 0.9, 0); rest area 0.45.
Mesh one_triangle() {
  Eigen::Matrix3Xd ref(3, 3);
  ref << 0.0, 1.0, 0.4,  //
      0.0, 0.0, 0.9,     //
      0.0, 0.0, 0.0;
  return build_mesh(ref, {{0, 1, 2}});
}

// The triangle with its apex lowered towards the base so that its area is `ratio` of the rest
// area, tilted out of the plane and jittered by `noise`.
State squashed(const Mesh& m, double ratio, unsigned seed, double noise = 1e-4) {
  State s;
  s.x = m.ref_flat();
  s.x.segment<3>(6) = Vec3(0.4, 0.9 * ratio * std::cos(0.3), 0.9 * ratio * std::sin(0.3));
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0.0, noise);
  for (Index k = 0; k < s.x.size(); ++k) s.x[k] += N(rng);
  s.v = VecX::Zero(s.x.size());
  s.p = VecX::Zero(m.num_hinges());
  return s;
}

double area(const VecX& x, const std::array<Index, 3>& t) {
  return 0.5 * (node(x, t[1]) - node(x, t[0])).cross(node(x, t[2]) - node(x, t[0])).norm();
}

// A grid sheet with every node displaced at random by `amp` of the spacing (0.2): some
// triangles lose more than half their area, some are turned over.
State crumpled_grid(const Mesh& m, unsigned seed, double amp) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0.0, amp);
  State s;
  s.x = m.ref_flat();
  for (Index k = 0; k < s.x.size(); ++k) s.x[k] += N(rng);
  s.v = VecX::Zero(s.x.size());
  s.p = VecX::Zero(m.num_hinges());
  return s;
}

}  // namespace

TEST(AreaBarrier, SilentAboveHalfTheRestArea) {
  const Mesh m = one_triangle();
  AreaBarrierTerm term(m, 3.0);
  for (double ratio : {1.0, 0.9, 0.6, 0.51, 1.7}) {
    const State s = squashed(m, ratio, 2, 0.0);
    EXPECT_TRUE(term.active_triangles(s.x).empty()) << ratio;
    EXPECT_EQ(term.energy(s), 0.0) << ratio;
    VecX f = VecX::Zero(s.x.size());
    term.add_force(s, f);
    EXPECT_EQ(f.norm(), 0.0) << ratio;
  }
}

TEST(AreaBarrier, ActiveBelowHalfTheRestArea) {
  const Mesh m = one_triangle();
  AreaBarrierTerm term(m, 3.0);
  for (double ratio : {0.49, 0.3, 0.01, 0.0}) {
    const State s = squashed(m, ratio, 2, 0.0);
    EXPECT_NEAR(term.squared_area_ratio(s.x, 0), ratio * ratio, 1e-12) << ratio;
    EXPECT_EQ(term.active_triangles(s.x), std::vector<Index>{0}) << ratio;
    EXPECT_GT(term.energy(s), 0.0) << ratio;
  }
}

TEST(AreaBarrier, FiniteDifferencesDownToZeroArea) {
  const Mesh m = one_triangle();
  AreaBarrierTerm term(m, 3.0);
  for (double ratio : {0.45, 0.3, 0.1, 0.02, 1e-3, 0.0}) {
    for (unsigned seed : {1u, 2u}) {
      const State s = squashed(m, ratio, seed);
      const FdReport r = check_term(term, s, m.num_hinges(), 1e-7);
      SCOPED_TRACE("area ratio " + std::to_string(ratio) + " seed " + std::to_string(seed));
      EXPECT_GT(r.force_norm + r.hx_norm, 0.0);
      EXPECT_LT(r.force, 1e-6);
      EXPECT_LT(r.hx, 1e-6);
      EXPECT_LT(r.hx_asymmetry, 1e-12);
    }
  }
}

TEST(AreaBarrier, FiniteDifferencesOnACrumpledSheet) {
  const Mesh m = grid_mesh(6, 5, 1.0, 0.8, 0.2, 3);
  AreaBarrierTerm term(m, 3.0);
  for (unsigned seed : {4u, 5u, 6u}) {
    const State s = crumpled_grid(m, seed, 0.08);
    ASSERT_GE(term.active_triangles(s.x).size(), 2u) << seed;
    const FdReport r = check_term(term, s, m.num_hinges(), 1e-7);
    SCOPED_TRACE(seed);
    EXPECT_LT(r.force, 1e-6);
    EXPECT_LT(r.hx, 1e-6);
    EXPECT_LT(r.hx_asymmetry, 1e-12);
  }
}

// Continuous to second order at the onset: the energy and the force fall to zero as the area
// ratio rises to 1/2, the energy as the cube of the distance.
TEST(AreaBarrier, VanishesSmoothlyAtTheOnset) {
  const Mesh m = one_triangle();
  AreaBarrierTerm term(m, 3.0);
  double prev_e = 0, prev_f = 0;
  for (double gap : {1e-1, 1e-2, 1e-3}) {
    const State s = squashed(m, AreaBarrierTerm::kOnset - gap, 0, 0.0);
    const double e = term.energy(s);
    VecX f = VecX::Zero(s.x.size());
    term.add_force(s, f);
    if (prev_e > 0) {
      EXPECT_NEAR(prev_e / e, 1e3, 2e2) << gap;  // ~ gap^3
      EXPECT_NEAR(prev_f / f.norm(), 1e2, 2e1) << gap;  // ~ gap^2
    }
    prev_e = e;
    prev_f = f.norm();
  }
}

TEST(AreaBarrier, PushesTheTriangleOpenAndGrowsSteeply) {
  const Mesh m = one_triangle();
  const double ks = 3.0;
  AreaBarrierTerm term(m, ks);
  double prev = 0;
  for (double ratio : {0.4, 0.2, 0.1, 0.01, 1e-3}) {
    const State s = squashed(m, ratio, 0, 0.0);
    const double e = term.energy(s);
    EXPECT_GT(e, prev) << ratio;
    prev = e;
    VecX f = VecX::Zero(s.x.size());
    term.add_force(s, f);
    State t = s;
    t.x += 1e-6 / f.norm() * f;
    EXPECT_GT(area(t.x, m.triangles[0]), area(s.x, m.triangles[0])) << ratio;
  }
  // Finite at zero area: 50 K with K = ks times the mean squared rest edge.
  const double l2 = (1.0 + 0.4 * 0.4 + 0.9 * 0.9 + 0.6 * 0.6 + 0.9 * 0.9) / 3.0;
  EXPECT_NEAR(term.energy(squashed(m, 0.0, 0, 0.0)), 50.0 * ks * l2, 1e-9);
  EXPECT_GT(prev, 100.0 * term.energy(squashed(m, 0.4, 0, 0.0)));
}

TEST(AreaBarrier, NoNetForceOrTorqueAndRigidInvariance) {
  const Mesh m = grid_mesh(6, 5, 1.0, 0.8, 0.2, 3);
  AreaBarrierTerm term(m, 3.0);
  const State s = crumpled_grid(m, 4, 0.08);
  VecX f = VecX::Zero(s.x.size());
  term.add_force(s, f);
  ASSERT_GT(f.norm(), 0.0);
  Vec3 net = Vec3::Zero(), torque = Vec3::Zero();
  for (Index i = 0; i < m.num_nodes(); ++i) {
    net += node(f, i);
    torque += node(s.x, i).cross(node(f, i));
  }
  EXPECT_LE(net.norm(), 1e-12 * f.norm());
  EXPECT_LE(torque.norm(), 1e-12 * f.norm());
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Vec3(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  State moved = s;
  for (Index i = 0; i < m.num_nodes(); ++i)
    moved.x.segment<3>(3 * i) = R * node(s.x, i) + Vec3(1.5, -2.0, 0.3);
  EXPECT_NEAR(term.energy(moved), term.energy(s), 1e-12 * term.energy(s));
}

TEST(AreaBarrier, ActiveTrianglesAreThoseBelowTheOnset) {
  const Mesh m = grid_mesh(8, 8, 1.0, 1.0, 0.2, 5);
  AreaBarrierTerm term(m, 1.0);
  std::size_t found = 0;
  for (unsigned seed = 0; seed < 10; ++seed) {
    const State s = crumpled_grid(m, seed, 0.05);
    std::vector<Index> brute;
    for (Index t = 0; t < m.num_triangles(); ++t)
      if (area(s.x, m.triangles[t]) < AreaBarrierTerm::kOnset * m.triangle_area(t))
        brute.push_back(t);
    EXPECT_EQ(term.active_triangles(s.x), brute) << seed;
    found += brute.size();
  }
  EXPECT_GT(found, 10u);
}

TEST(AreaBarrier, RefusesAnOnsetOutsideZeroToOne) {
  const Mesh m = one_triangle();
  EXPECT_THROW(AreaBarrierTerm(m, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(AreaBarrierTerm(m, 1.0, 1.0), std::invalid_argument);
}

// The sheet model holds the barrier (as stretching energy) unless the material switches it off.
TEST(AreaBarrier, PartOfTheSheetModelUnlessSwitchedOff) {
  const Mesh m = grid_mesh(6, 5, 1.0, 0.8, 0.2, 3);
  const State s = crumpled_grid(m, 4, 0.08);
  ModelParams on, off;
  off.area_barrier = false;
  SheetModel with(m, on), without(m, off);
  AreaBarrierTerm term(m, on.ks);
  EXPECT_NEAR(with.energies(s).stretch - without.energies(s).stretch, term.energy(s),
              1e-12 * term.energy(s));
  int named = 0;
  for (const auto& e : with.terms()) named += e.term->name() == "area_barrier";
  EXPECT_EQ(named, 1);
  for (const auto& e : without.terms()) EXPECT_NE(e.term->name(), "area_barrier");
}
