// The fold barrier (sim/contact/fold_barrier.hpp): silent until a hinge is nearly folded flat
// onto itself, then a force that opens it, with exact derivatives (finite differences) on both
// sides of theta = 0, and an energy that grows steeply as the fold closes.
#include "sim/contact/fold_barrier.hpp"
#include "sim/model/hinge_geometry.hpp"
#include "tests/support/finite_diff.hpp"
#include "tests/support/grid_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace crumple;
using namespace crumple::testing;

namespace {

// One hinge: x0 = (0,0,0), x1 = (1,0,0), wings of altitude 0.85 and 0.8.
Mesh one_hinge() {
  Eigen::Matrix3Xd ref(3, 4);
  ref << 0.0, 1.0, 0.45, 0.55,  //
      0.0, 0.0, 0.85, -0.8,     //
      0.0, 0.0, 0.0, 0.0;
  return build_mesh(ref, {{0, 1, 2}, {1, 0, 3}});
}

// The hinge with the wing of x3 turned about the hinge edge (the x axis) by `angle` (radians):
// bend angle +-angle depending on the direction.
State folded(const Mesh& m, double angle, unsigned seed) {
  State s;
  s.x = m.ref_flat();
  const Index tip = m.hinges[0].nodes[3];
  const double y = m.ref(1, tip);
  s.x.segment<3>(3 * tip) = Vec3(m.ref(0, tip), y * std::cos(angle), y * std::sin(angle));
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0.0, 1e-3);
  for (Index k = 0; k < s.x.size(); ++k) s.x[k] += N(rng);
  s.v = VecX::Zero(s.x.size());
  s.p = VecX::Zero(m.num_hinges());
  return s;
}

double theta_of(const Mesh& m, const State& s) {
  const auto& nd = m.hinges[0].nodes;
  return bend_angle(node(s.x, nd[0]), node(s.x, nd[1]), node(s.x, nd[2]), node(s.x, nd[3]));
}

}  // namespace

TEST(FoldBarrier, OnsetFromRangeAndWingAltitude) {
  const Mesh m = one_hinge();
  ASSERT_EQ(m.num_hinges(), 1);
  FoldBarrierTerm term(m, 2.0, 0.1);
  EXPECT_NEAR(term.onset(0), 0.1 / 0.8, 1e-12);
}

TEST(FoldBarrier, SilentBelowOnset) {
  const Mesh m = one_hinge();
  FoldBarrierTerm term(m, 2.0, 0.1);  // onset: opening 0.125 rad, a fold of 172.8 degrees
  for (double deg : {0.0, 30.0, -90.0, 170.0, -170.0}) {
    const State s = folded(m, deg * M_PI / 180, 3);
    EXPECT_EQ(term.energy(s), 0.0) << deg;
    VecX f = VecX::Zero(s.x.size());
    term.add_force(s, f);
    EXPECT_EQ(f.norm(), 0.0) << deg;
  }
}

TEST(FoldBarrier, FiniteDifferencesNearACompleteFold) {
  const Mesh m = one_hinge();
  FoldBarrierTerm term(m, 2.0, 0.1);
  for (double deg : {176.0, -176.0, 179.0, -179.0}) {
    const State s = folded(m, deg * M_PI / 180, 7);
    ASSERT_NEAR(std::abs(theta_of(m, s)), std::abs(deg) * M_PI / 180, 0.01) << deg;
    EXPECT_GT(term.energy(s), 0.0) << deg;
    const FdReport r = check_term(term, s, m.num_hinges(), 1e-8);
    EXPECT_LT(r.force, 1e-6) << deg;
    EXPECT_LT(r.hx, 1e-6) << deg;
    EXPECT_LT(r.hx_asymmetry, 1e-12) << deg;
  }
}

TEST(FoldBarrier, PushesTheFoldOpenAndGrowsSteeply) {
  const Mesh m = one_hinge();
  FoldBarrierTerm term(m, 2.0, 0.1);
  double prev = 0;
  for (double deg : {174.0, 177.0, 179.0, 179.9, 179.99}) {
    const State s = folded(m, deg * M_PI / 180, 0);
    const double e = term.energy(s);
    EXPECT_GT(e, prev) << deg;
    prev = e;
    // A small step along the force opens the fold.
    VecX f = VecX::Zero(s.x.size());
    term.add_force(s, f);
    State t = s;
    t.x += 1e-6 / f.norm() * f;
    EXPECT_LT(std::abs(theta_of(m, t)), std::abs(theta_of(m, s))) << deg;
  }
  EXPECT_GT(prev, 1e2 * term.energy(folded(m, 174.0 * M_PI / 180, 0)));
}

TEST(FoldBarrier, FlatSheetFeelsNothing) {
  const Mesh m = grid_mesh(8, 8, 1.0, 1.0, 0.2, 3);
  FoldBarrierTerm term(m, 1.0, 0.5 * m.mean_edge_length());
  State s;
  s.x = m.ref_flat();
  EXPECT_TRUE(term.active_hinges(s.x).empty());
  EXPECT_EQ(term.energy(s), 0.0);
}

// The active set comes from a test on cos(theta) without the bend angle (fold_barrier.cpp): it
// must pick exactly the hinges whose opening pi - |theta| is below the onset, also within
// rounding of the onset and on a randomly crumpled sheet.
TEST(FoldBarrier, ActiveHingesAreThoseOpenedLessThanTheOnset) {
  const auto brute = [](const Mesh& m, const FoldBarrierTerm& term, const VecX& x) {
    std::vector<Index> out;
    for (Index h = 0; h < m.num_hinges(); ++h) {
      const auto& nd = m.hinges[h].nodes;
      const double th = bend_angle(node(x, nd[0]), node(x, nd[1]), node(x, nd[2]), node(x, nd[3]));
      if (M_PI - std::abs(th) < term.onset(h)) out.push_back(h);
    }
    return out;
  };
  const Mesh one = one_hinge();
  FoldBarrierTerm t1(one, 2.0, 0.1);
  int active = 0, idle = 0;
  for (int k = -200; k <= 200; ++k) {
    // Bend angles around the onset, 1e-10 rad apart near it, both signs.
    const double off = std::copysign(1e-10 * std::pow(1.12, std::abs(k)), k);
    for (double sgn : {1.0, -1.0}) {
      VecX x = one.ref_flat();  // the wing of x3 turned about the hinge edge, no noise
      const Index tip = one.hinges[0].nodes[3];
      const double y = one.ref(1, tip), ang = sgn * (M_PI - t1.onset(0) + off);
      x.segment<3>(3 * tip) = Vec3(one.ref(0, tip), y * std::cos(ang), y * std::sin(ang));
      const auto got = t1.active_hinges(x);
      EXPECT_EQ(got, brute(one, t1, x)) << k << " " << sgn;
      (got.empty() ? idle : active)++;
    }
  }
  EXPECT_GT(active, 100);
  EXPECT_GT(idle, 100);

  const Mesh m = grid_mesh(12, 12, 1.0, 1.0, 0.2, 5);
  FoldBarrierTerm term(m, 1.0, 0.5 * m.mean_edge_length());
  std::mt19937_64 rng(11);
  std::normal_distribution<double> N(0.0, 0.7 * m.mean_edge_length());
  std::size_t found = 0;
  for (int trial = 0; trial < 20; ++trial) {
    VecX x = m.ref_flat();
    for (Index k = 0; k < x.size(); ++k) x[k] += N(rng);
    const auto want = brute(m, term, x);
    EXPECT_EQ(term.active_hinges(x), want) << trial;
    found += want.size();
  }
  EXPECT_GT(found, 20u);  // the crumpled sheets do have nearly complete folds
}
