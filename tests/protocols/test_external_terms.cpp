// External terms of protocol stages against finite differences: walls (plane, cylinder inside
// and outside, sphere, cone), moving pistons, ramped tethers.
#include "protocols/terms/tether_term.hpp"
#include "protocols/terms/wall_term.hpp"
#include "tests/support/finite_diff.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace crumple;
using crumple::testing::check_term;

namespace {
// A cloud of nodes around the origin, some of them within reach of every wall below.
State cloud(unsigned seed, double t = 0.3) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  State s;
  const Index n = 40;
  s.x.resize(3 * n);
  for (Index k = 0; k < 3 * n; ++k) s.x[k] = U(rng);
  s.v = VecX::Zero(3 * n);
  s.p = VecX::Zero(0);
  s.t = t;
  return s;
}

void expect_wall_ok(std::shared_ptr<const Wall> wall, double range) {
  const State s = cloud(3);
  WallTerm term(wall, s.x.size() / 3, 5.0, range);
  const auto r = check_term(term, s, 0, 1e-7);
  SCOPED_TRACE(wall->name());
  EXPECT_GT(r.force_norm, 0.0) << "no node within reach: the test would prove nothing";
  EXPECT_LE(r.force, 1e-6);
  EXPECT_LE(r.hx, 1e-6);
  EXPECT_LE(r.hx_asymmetry, 1e-12);
}
}  // namespace

TEST(Walls, FiniteDifferences) {
  expect_wall_ok(std::make_shared<PlaneWall>(Vec3(0, 0, -0.5), Vec3(0.2, 0.1, 1.0),
                                             LinearMotion{0.0, 0.4, 0.0}),
                 0.3);
  expect_wall_ok(std::make_shared<CylinderWall>(Vec3(0.1, 0, 0), Vec3(0, 0.3, 1),
                                                LinearMotion{0.9, -0.2, 0.0}, true),
                 0.3);
  expect_wall_ok(std::make_shared<CylinderWall>(Vec3(0, 0, 0), Vec3(1, 0, 0),
                                                LinearMotion{0.5, 0.0, 0.0}, false),
                 0.3);
  expect_wall_ok(std::make_shared<SphereWall>(Vec3(0, 0.1, 0), LinearMotion{1.1, -0.5, 0.0}, true),
                 0.4);
  expect_wall_ok(std::make_shared<SphereWall>(Vec3(0, 0, 0), LinearMotion{0.6, 0.0, 0.0}, false),
                 0.3);
  expect_wall_ok(std::make_shared<ConeWall>(Vec3(0, 0, -1.5), Vec3(0, 0, 1), 0.4, true), 0.3);
}

TEST(Walls, SaturatingProfileFiniteDifferences) {
  const State s = cloud(4);
  WallProfile prof;
  prof.kind = WallProfile::Kind::Saturating;
  prof.f_max = 2.0;
  prof.width = 0.2;
  WallTerm term(std::make_shared<SphereWall>(Vec3(0, 0, 0), LinearMotion{0.8, 0.0, 0.0}, true),
                s.x.size() / 3, prof, 0.0);
  const auto r = check_term(term, s, 0, 1e-7);
  EXPECT_GT(r.force_norm, 0.0);
  EXPECT_LE(r.force, 1e-6);
  EXPECT_LE(r.hx, 1e-6);
  double U, F, dF;
  prof.eval(50.0, U, F, dF);
  EXPECT_NEAR(F, 2.0, 1e-12);  // bounded
  prof.eval(0.0, U, F, dF);
  EXPECT_EQ(F, 0.0);
  EXPECT_EQ(dF, 0.0);  // C^2 energy at the cutoff
}

TEST(Walls, PotentialIsOneSidedAndSmooth) {
  auto wall = std::make_shared<PlaneWall>(Vec3(0, 0, 0), Vec3(0, 0, 1));
  WallTerm term(wall, 1, 2.0, 0.1);
  State s;
  s.v = VecX::Zero(3);
  s.p = VecX::Zero(0);
  auto force_at = [&](double z) {
    s.x = Vec3(0, 0, z);
    VecX f = VecX::Zero(3);
    term.add_force(s, f);
    return f.z();
  };
  EXPECT_EQ(force_at(0.1000001), 0.0);
  EXPECT_NEAR(force_at(0.0999999), 0.0, 1e-12);  // continuous (and C^1) at the range
  EXPECT_NEAR(force_at(0.0), 2.0 * 0.01, 1e-15);   // k range^2 at contact
  EXPECT_GT(force_at(-0.05), force_at(0.0));        // stiffer inside
}

TEST(Walls, PistonMovesToItsTarget) {
  PlaneWall piston(Vec3(0, 0, 1), Vec3(0, 0, -1), LinearMotion{0.0, 0.5, 0.0, 0.3});
  EXPECT_DOUBLE_EQ(piston.offset(0.4), 0.2);
  EXPECT_DOUBLE_EQ(piston.offset(2.0), 0.3);
}

TEST(Tethers, FiniteDifferences) {
  const State s = cloud(5, 0.25);
  auto targets = [](double t, Eigen::Matrix3Xd& out) {
    for (Index a = 0; a < out.cols(); ++a) out.col(a) = Vec3(0.1 * a, t, -0.2);
  };
  TetherTerm term({1, 4, 7, 9}, targets, 3.0, 0.0, 1.0);
  const auto r = check_term(term, s, 0, 1e-7);
  EXPECT_GT(r.force_norm, 0.0);
  EXPECT_LE(r.force, 1e-6);
  EXPECT_LE(r.hx, 1e-6);
  EXPECT_DOUBLE_EQ(term.stiffness(0.25), 0.75);
  EXPECT_DOUBLE_EQ(term.stiffness(5.0), 3.0);
}
