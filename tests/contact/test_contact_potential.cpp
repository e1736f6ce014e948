// The contact law (eq. 10, B.9-B.10) and its distribution over two barycentric sites (eq. 11-12)
// against finite differences, at distances across the range, and its smooth vanishing at sigma.
#include "sim/contact/contact_potential.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

using namespace crumple;

namespace {

constexpr double kTol = 1e-6;

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> N;
  return Vec3(N(rng), N(rng), N(rng)).normalized();
}

std::array<double, 3> random_weights(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  double a = U(rng), b = U(rng);
  if (a + b > 1) a = 1 - a, b = 1 - b;
  return {a, b, 1 - a - b};
}

// Two sites on two triangles (6 nodes, 18 dofs): site 1 = sum w_k x_k (k = 0..2), site 2 =
// sum w_k x_k (k = 3..5). Energy, node forces c_a F1 and Hx blocks c_a c_b K as in the term.
struct Stencil {
  ContactLaw law;
  std::array<double, 6> c;  // +w on site 1, -w on site 2

  Vec3 r(const VecX& x) const {
    Vec3 v = Vec3::Zero();
    for (int a = 0; a < 6; ++a) v += c[a] * x.segment<3>(3 * a);
    return v;
  }
  double energy(const VecX& x) const { return law.energy(r(x).norm()); }
  VecX force(const VecX& x) const {
    const Vec3 F1 = law.force(r(x));
    VecX f(18);
    for (int a = 0; a < 6; ++a) f.segment<3>(3 * a) = c[a] * F1;
    return f;
  }
  Eigen::MatrixXd hx(const VecX& x) const {
    const Mat3 K = law.stiffness(r(x));
    Eigen::MatrixXd H(18, 18);
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) H.block<3, 3>(3 * a, 3 * b) = c[a] * c[b] * K;
    return H;
  }
};

// Builds two random triangles whose sites (random weights) are `d` apart.
VecX place(const Stencil& st, std::mt19937_64& rng, double d, double size) {
  std::normal_distribution<double> N;
  VecX x(18);
  for (int k = 0; k < 18; ++k) x[k] = size * N(rng);
  const Vec3 shift = d * random_unit(rng) - st.r(x);
  for (int a = 0; a < 3; ++a) x.segment<3>(3 * a) += shift;  // site 1 weights sum to one
  return x;
}

}  // namespace

TEST(ContactLaw, EnergyClosedFormMatchesForceMagnitude) {
  // E(d) = ks sigma^2 e^rho must satisfy -E'(d) = f(d); compare with a 5-point derivative.
  const ContactLaw law{2.5, 0.4};
  for (double t : {0.05, 0.3, 0.5, 0.7, 0.9, 0.95}) {
    const double d = t * law.sigma, h = 1e-4 * law.sigma;
    const double dE = (-law.energy(d + 2 * h) + 8 * law.energy(d + h) - 8 * law.energy(d - h) +
                       law.energy(d - 2 * h)) / (12 * h);
    EXPECT_NEAR(-dE, law.magnitude(d), 1e-8 * law.ks * law.sigma) << "d/sigma = " << t;
  }
  // Bounded at zero separation: E(0) = ks sigma^2 / e.
  EXPECT_NEAR(law.energy(0.0), law.ks * law.sigma * law.sigma * std::exp(-1.0), 1e-15);
}

TEST(ContactLaw, VanishesSmoothlyAtRange) {
  const ContactLaw law{1.0, 1.0};
  EXPECT_EQ(law.energy(1.0), 0.0);
  EXPECT_EQ(law.energy(1.5), 0.0);
  EXPECT_EQ(law.force(Vec3(0, 0, 1.0)).norm(), 0.0);
  // Approaching sigma from inside, energy, force and stiffness all decrease to zero.
  double e_prev = law.energy(0.9), f_prev = law.magnitude(0.9);
  double k_prev = law.stiffness(Vec3(0.9, 0, 0)).norm();
  for (double d : {0.95, 0.98, 0.99, 0.995, 0.999}) {
    const double e = law.energy(d), f = law.magnitude(d);
    const double k = law.stiffness(Vec3(d, 0, 0)).norm();
    EXPECT_LT(e, e_prev);
    EXPECT_LT(f, f_prev);
    EXPECT_LT(k, k_prev);
    e_prev = e, f_prev = f, k_prev = k;
  }
  EXPECT_LT(law.energy(0.99), 1e-40);
  EXPECT_LT(law.magnitude(0.99), 1e-35);
  EXPECT_LT(law.stiffness(Vec3(0.99, 0, 0)).norm(), 1e-30);
  // No NaN from rho^2 e^rho when rho is huge.
  EXPECT_EQ(law.force(Vec3(1.0 - 1e-15, 0, 0)).norm(), 0.0);
  EXPECT_TRUE(law.stiffness(Vec3(1.0 - 1e-13, 0, 0)).allFinite());
}

TEST(ContactLaw, RepulsiveAlongSeparation) {
  const ContactLaw law{1.0, 0.3};
  const Vec3 r(0.1, -0.05, 0.07);
  const Vec3 F = law.force(r);
  EXPECT_GT(F.dot(r), 0.0);
  EXPECT_LT(F.cross(r).norm(), 1e-14 * F.norm() * r.norm());
  const Mat3 K = law.stiffness(r);
  EXPECT_LT((K - K.transpose()).norm(), 1e-14 * K.norm());
}

TEST(ContactLaw, BarycentricStencilAgainstFiniteDifferences) {
  std::mt19937_64 rng(7);
  const double h = 1e-6;
  for (double sigma : {0.05, 1.0}) {
    for (double t : {0.3, 0.45, 0.6, 0.75, 0.9, 0.95}) {
      for (int trial = 0; trial < 3; ++trial) {
        Stencil st{{1.7, sigma}, {}};
        const auto w1 = random_weights(rng), w2 = random_weights(rng);
        for (int k = 0; k < 3; ++k) st.c[k] = w1[k], st.c[3 + k] = -w2[k];
        const VecX x = place(st, rng, t * sigma, sigma);
        ASSERT_NEAR(st.r(x).norm(), t * sigma, 1e-12 * sigma);
        const double hh = h * sigma;
        VecX grad(18);
        Eigen::MatrixXd H_fd(18, 18);
        for (int k = 0; k < 18; ++k) {
          VecX a = x, b = x;
          a[k] += hh;
          b[k] -= hh;
          grad[k] = (st.energy(a) - st.energy(b)) / (2 * hh);
          H_fd.col(k) = -(st.force(a) - st.force(b)) / (2 * hh);
        }
        const VecX f = st.force(x);
        EXPECT_LT((f + grad).norm() / grad.norm(), kTol) << "sigma " << sigma << " d/s " << t;
        EXPECT_LT((st.hx(x) - H_fd).norm() / H_fd.norm(), kTol) << "sigma " << sigma << " d/s " << t;
        // Momentum and angular momentum: forces sum to zero and exert no torque.
        Vec3 sum = Vec3::Zero(), torque = Vec3::Zero();
        for (int a = 0; a < 6; ++a) {
          sum += f.segment<3>(3 * a);
          torque += Vec3(x.segment<3>(3 * a)).cross(Vec3(f.segment<3>(3 * a)));
        }
        EXPECT_LT(sum.norm(), 1e-14 * f.norm());
        EXPECT_LT(torque.norm(), 1e-12 * f.norm() * x.norm());
      }
    }
  }
}
