// Finite-difference checks of the bend angle, its gradient and Hessian (hinge_geometry.hpp),
// at random states, at the flat state and with the hinge folded to 170 degrees.
#include "sim/model/hinge_geometry.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace crumple;

namespace {
std::array<Vec3, 4> flat_hinge() {
  return {Vec3(0, 0, 0), Vec3(1, 0.1, 0), Vec3(0.4, 0.9, 0), Vec3(0.6, -0.8, 0)};
}
// Rotates x3 about the hinge edge so that the bend angle becomes theta.
std::array<Vec3, 4> folded_hinge(double theta) {
  auto x = flat_hinge();
  const Vec3 axis = (x[1] - x[0]).normalized();
  const Eigen::AngleAxisd rot(theta, axis);
  x[3] = x[0] + rot * (x[3] - x[0]);
  return x;
}
Vec12 pack(const std::array<Vec3, 4>& x) {
  Vec12 v;
  for (int i = 0; i < 4; ++i) v.segment<3>(3 * i) = x[i];
  return v;
}
double angle_of(const Vec12& v) {
  return bend_angle(v.segment<3>(0), v.segment<3>(3), v.segment<3>(6), v.segment<3>(9));
}
void check_derivatives(const std::array<Vec3, 4>& x) {
  Vec12 g;
  Mat12 H;
  const double th = bend_angle_derivatives(x[0], x[1], x[2], x[3], g, &H);
  const Vec12 v = pack(x);
  EXPECT_NEAR(th, angle_of(v), 1e-14);
  const double h = 1e-6;
  Vec12 gfd;
  Mat12 Hfd;
  for (int i = 0; i < 12; ++i) {
    Vec12 a = v, b = v;
    a[i] += h;
    b[i] -= h;
    gfd[i] = (angle_of(a) - angle_of(b)) / (2 * h);
    Vec12 ga, gb;
    std::array<Vec3, 4> xa, xb;
    for (int k = 0; k < 4; ++k) {
      xa[k] = a.segment<3>(3 * k);
      xb[k] = b.segment<3>(3 * k);
    }
    bend_angle_derivatives(xa[0], xa[1], xa[2], xa[3], ga, nullptr);
    bend_angle_derivatives(xb[0], xb[1], xb[2], xb[3], gb, nullptr);
    Hfd.col(i) = (ga - gb) / (2 * h);
  }
  EXPECT_LE((g - gfd).norm(), 1e-7 * g.norm()) << "theta = " << th;
  EXPECT_LE((H - Hfd).norm(), 1e-6 * H.norm()) << "theta = " << th;
  EXPECT_LE((H - H.transpose()).norm(), 1e-10 * H.norm());
}
// The flat and two folded hinges, then 20 random perturbations of the flat one.
std::vector<std::array<Vec3, 4>> sample_hinges(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0.0, 0.3);
  std::vector<std::array<Vec3, 4>> cases{flat_hinge(), folded_hinge(2.9), folded_hinge(-1.1)};
  for (int k = 0; k < 20; ++k) {
    auto x = flat_hinge();
    for (auto& p : x) p += Vec3(N(rng), N(rng), N(rng));
    cases.push_back(x);
  }
  return cases;
}
}  // namespace

TEST(HingeGeometry, SignConvention) {
  // Lifting x2 above the plane tilts n1 towards T2: normals point towards each other, theta < 0.
  auto x = flat_hinge();
  x[2].z() = 0.1;
  EXPECT_LT(bend_angle(x[0], x[1], x[2], x[3]), 0.0);
  x[2].z() = -0.1;
  EXPECT_GT(bend_angle(x[0], x[1], x[2], x[3]), 0.0);
  EXPECT_NEAR(bend_angle(flat_hinge()[0], flat_hinge()[1], flat_hinge()[2], flat_hinge()[3]), 0.0,
              1e-15);
}

TEST(HingeGeometry, FoldAngleIsExact) {
  for (double th : {-2.5, -0.3, 0.0, 0.7, 2.9}) {
    auto x = folded_hinge(th);
    EXPECT_NEAR(bend_angle(x[0], x[1], x[2], x[3]), th, 1e-12);
  }
}

TEST(HingeGeometry, DerivativesAtFlatState) { check_derivatives(flat_hinge()); }

TEST(HingeGeometry, DerivativesFoldedTo170Degrees) {
  check_derivatives(folded_hinge(170.0 * M_PI / 180.0));
  check_derivatives(folded_hinge(-170.0 * M_PI / 180.0));
}

TEST(HingeGeometry, DerivativesAtRandomStates) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> N(0.0, 0.15);
  for (int trial = 0; trial < 20; ++trial) {
    auto x = folded_hinge(std::uniform_real_distribution<double>(-2.5, 2.5)(rng));
    for (auto& p : x) p += Vec3(N(rng), N(rng), N(rng));
    check_derivatives(x);
  }
}

TEST(HingeGeometry, GradientKillsRigidMotions) {
  auto x = folded_hinge(0.8);
  Vec12 g;
  Mat12 H;
  bend_angle_derivatives(x[0], x[1], x[2], x[3], g, &H);
  for (int d = 0; d < 3; ++d) {
    Vec12 t = Vec12::Zero();
    for (int k = 0; k < 4; ++k) t[3 * k + d] = 1.0;
    EXPECT_NEAR(g.dot(t), 0.0, 1e-12);
    EXPECT_LE((H * t).norm(), 1e-10 * H.norm());
  }
}

TEST(HingeGeometry, CurvatureWithoutTrigonometryMatchesTheAngle) {
  for (double th : {-3.0, -1.2, -1e-7, 0.0, 1e-7, 0.4, 2.2, 3.1}) {
    auto x = folded_hinge(th);
    EXPECT_NEAR(hinge_curvature(x[0], x[1], x[2], x[3]), 2.0 * std::sin(0.5 * th), 1e-14);
  }
}

// The gradient-only path of bend_half_angle_derivatives (every force evaluation) computes the
// same gradient and half angles as the path that also forms the Hessian (finite-difference
// checked above through bend_angle_derivatives), and grad(theta) is that gradient.
TEST(HingeGeometry, GradientOnlyPathMatchesTheHessianPath) {
  for (const auto& x : sample_hinges(4)) {
    Vec12 g1, g2, g3;
    Mat12 H;
    const HalfAngle a = bend_half_angle_derivatives(x[0], x[1], x[2], x[3], g1, nullptr);
    const HalfAngle b = bend_half_angle_derivatives(x[0], x[1], x[2], x[3], g2, &H);
    const double th = bend_angle_derivatives(x[0], x[1], x[2], x[3], g3, nullptr);
    EXPECT_LE((g1 - g2).norm(), 1e-14 * g2.norm());
    EXPECT_LE((g1 - g3).norm(), 1e-14 * g3.norm());
    EXPECT_NEAR(a.sin_half, b.sin_half, 1e-15);
    EXPECT_NEAR(a.cos_half, b.cos_half, 1e-15);
    EXPECT_NEAR(a.sin_half, std::sin(0.5 * th), 1e-14);
    EXPECT_NEAR(a.cos_half, std::cos(0.5 * th), 1e-14);
  }
}

// The gradient from precomputed triangle frames (BendingTerm's force path on an oriented mesh)
// is the gradient-only path's, and a frame of the wrong orientation is not silently accepted.
TEST(HingeGeometry, GradientFromTriangleFramesMatches) {
  for (const auto& x : sample_hinges(9)) {
    Vec12 g1, g2, g3;
    const HalfAngle a = bend_half_angle_derivatives(x[0], x[1], x[2], x[3], g1, nullptr);
    // T2's frame from a rotation of (x1, x0, x3): the frame depends only on the cyclic order.
    const TriangleFrame t1 = triangle_frame(x[0], x[1], x[2]);
    const TriangleFrame t2 = triangle_frame(x[3], x[1], x[0]);
    const HalfAngle b = bend_half_angle_gradient(x[0], x[1], x[2], x[3], t1, t2, g2);
    EXPECT_LE((g1 - g2).norm(), 1e-13 * g1.norm());
    EXPECT_NEAR(a.sin_half, b.sin_half, 1e-14);
    EXPECT_NEAR(a.cos_half, b.cos_half, 1e-14);
    const TriangleFrame flipped = triangle_frame(x[0], x[1], x[3]);  // T2 listed backwards
    bend_half_angle_gradient(x[0], x[1], x[2], x[3], t1, flipped, g3);
    EXPECT_GT((g1 - g3).norm(), 1e-3 * g1.norm());
  }
}
