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
