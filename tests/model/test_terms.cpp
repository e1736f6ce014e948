// Every internal force term against finite differences (force vs energy gradient, Hx, Hv, Hp),
// at random states, at the flat state and with the sheet folded to 170 degrees.
#include "sim/model/bending.hpp"
#include "sim/model/damping.hpp"
#include "sim/model/springs.hpp"
#include "tests/support/finite_diff.hpp"
#include "tests/support/grid_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

using namespace crumple;
using crumple::testing::check_term;
using crumple::testing::grid_mesh;

namespace {

constexpr double kTol = 1e-6;

const Mesh& test_mesh() {
  static const Mesh m = grid_mesh(6, 5, 1.0, 0.8, 0.2, 3);
  return m;
}

State random_state(const Mesh& m, unsigned seed, double amp) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0.0, 1.0);
  State s;
  s.x = m.ref_flat();
  for (Index k = 0; k < s.x.size(); ++k) s.x[k] += amp * N(rng);
  s.v = VecX(s.x.size());
  for (Index k = 0; k < s.v.size(); ++k) s.v[k] = N(rng);
  s.p = VecX(m.num_hinges());
  for (Index k = 0; k < s.p.size(); ++k) s.p[k] = 0.3 * N(rng);
  return s;
}

State flat_state(const Mesh& m) {
  State s = random_state(m, 11, 0.0);
  s.x = m.ref_flat();
  return s;
}

// Folds the grid about the node column closest to x = 0.5 so the hinges on it reach `theta`.
State folded_state(const Mesh& m, double theta) {
  State s = random_state(m, 5, 0.0);
  s.x = m.ref_flat();
  const double xf = m.ref(0, 2);  // third column of the 6 x 5 grid (boundary nodes are unjittered)
  for (Index i = 0; i < m.num_nodes(); ++i) {
    const double dx = m.ref(0, i) - xf;
    if (dx > 1e-12) {
      s.x[3 * i] = xf + dx * std::cos(theta);
      s.x[3 * i + 2] = dx * std::sin(theta);
    }
  }
  return s;
}

using TermFactory = std::function<std::unique_ptr<ForceTerm>(const Mesh&)>;

struct Case {
  const char* name;
  TermFactory make;
};

std::vector<Case> all_terms() {
  return {
      {"springs", [](const Mesh& m) { return std::make_unique<SpringTerm>(m, 3.0); }},
      {"bending_per_triangle",
       [](const Mesh& m) {
         return std::make_unique<BendingTerm>(m, 0.7, BendingTerm::Assembly::PerTriangle);
       }},
      {"bending_per_hinge",
       [](const Mesh& m) {
         return std::make_unique<BendingTerm>(m, 0.7, BendingTerm::Assembly::PerHinge);
       }},
      {"drag", [](const Mesh& m) { return std::make_unique<DragTerm>(m.num_nodes(), 0.4); }},
      {"internal_damping",
       [](const Mesh& m) { return std::make_unique<InternalDampingTerm>(m, 0.9); }},
  };
}

void expect_fd_ok(const Case& c, const State& s, const char* where) {
  const Mesh& m = test_mesh();
  auto term = c.make(m);
  const auto r = check_term(*term, s, m.num_hinges());
  SCOPED_TRACE(std::string(c.name) + " at " + where);
  EXPECT_LE(r.force, kTol);
  EXPECT_LE(r.hx, kTol);
  EXPECT_LE(r.hv, kTol);
  EXPECT_LE(r.hp, kTol);
  if (term->conservative()) {
    EXPECT_LE(r.hx_asymmetry, 1e-12);
  }
}

}  // namespace

TEST(ForceTerms, FiniteDifferencesAtRandomStates) {
  for (const auto& c : all_terms())
    for (unsigned seed : {1u, 2u, 3u}) expect_fd_ok(c, random_state(test_mesh(), seed, 0.05), "random");
}

TEST(ForceTerms, FiniteDifferencesAtFlatState) {
  for (const auto& c : all_terms()) expect_fd_ok(c, flat_state(test_mesh()), "flat");
}

TEST(ForceTerms, FiniteDifferencesFoldedTo170Degrees) {
  for (const auto& c : all_terms()) {
    expect_fd_ok(c, folded_state(test_mesh(), 170.0 * M_PI / 180.0), "+170 deg");
    expect_fd_ok(c, folded_state(test_mesh(), -170.0 * M_PI / 180.0), "-170 deg");
  }
}

TEST(ForceTerms, FoldedStateReachesTheAngle) {
  const Mesh& m = test_mesh();
  const State s = folded_state(m, 170.0 * M_PI / 180.0);
  BendingTerm b(m, 1.0);
  VecX c;
  b.curvatures(s.x, c);
  // The fold line follows the jittered node column, so the hinges on it sit near 170 degrees.
  const double theta_max = 2.0 * std::asin(0.5 * c.cwiseAbs().maxCoeff()) * 180.0 / M_PI;
  EXPECT_GT(theta_max, 165.0);
  EXPECT_LT(theta_max, 175.0);
}

TEST(ForceTerms, LastCurvaturesAreThoseOfTheLatestForce) {
  // The explicit right-hand side takes the plastic rate's curvatures from the bending term
  // after the force: they must be the state's, and follow it to the next state.
  const Mesh& m = test_mesh();
  BendingTerm b(m, 1.0);
  for (unsigned seed : {4u, 5u}) {
    const State s = random_state(m, seed, 0.08);
    VecX f = VecX::Zero(s.x.size()), c;
    b.add_force(s, f);
    const VecX c_cache = b.last_curvatures();
    b.curvatures(s.x, c);
    ASSERT_EQ(c_cache.size(), m.num_hinges());
    EXPECT_LT((c_cache - c).cwiseAbs().maxCoeff(), 1e-14) << "seed " << seed;
  }
}

TEST(ForceTerms, NoNetForceOrTorque) {
  const Mesh& m = test_mesh();
  const State s = random_state(m, 9, 0.08);
  for (const auto& c : all_terms()) {
    if (std::string(c.name) == "drag") continue;  // drag is external: it stops the sheet
    // The dashpot of eq. (9) damps d/dt(r - s r_hat), which is not rotation invariant: off its
    // rest length a dashpot exerts a torque -b (1 - s/|r|) r x u. It is checked separately.
    if (std::string(c.name) == "internal_damping") continue;
    auto term = c.make(m);
    VecX f = VecX::Zero(s.x.size());
    term->add_force(s, f);
    Vec3 net = Vec3::Zero(), torque = Vec3::Zero();
    for (Index i = 0; i < m.num_nodes(); ++i) {
      net += node(f, i);
      torque += node(s.x, i).cross(node(f, i));
    }
    SCOPED_TRACE(c.name);
    EXPECT_LE(net.norm(), 1e-12 * f.norm());
    EXPECT_LE(torque.norm(), 1e-12 * f.norm());
  }
}

TEST(ForceTerms, EnergyInvariantUnderRigidMotion) {
  const Mesh& m = test_mesh();
  const State s = random_state(m, 4, 0.08);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Vec3(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  const Vec3 t(1.5, -2.0, 0.3);
  State moved = s;
  for (Index i = 0; i < m.num_nodes(); ++i) moved.x.segment<3>(3 * i) = R * node(s.x, i) + t;
  for (const auto& c : all_terms()) {
    auto term = c.make(m);
    if (!term->conservative()) continue;
    SCOPED_TRACE(c.name);
    EXPECT_NEAR(term->energy(moved), term->energy(s), 1e-12 * (1 + term->energy(s)));
  }
}

TEST(ForceTerms, PerTriangleAssemblyEqualsPerHinge) {
  const Mesh& m = test_mesh();
  const State s = random_state(m, 8, 0.1);
  BendingTerm a(m, 1.3, BendingTerm::Assembly::PerTriangle);
  BendingTerm b(m, 1.3, BendingTerm::Assembly::PerHinge);
  std::vector<std::pair<Index, Index>> pairs;
  a.coupled_pairs(pairs);
  BlockPattern pat(m.num_nodes(), pairs);
  a.bind(pat);
  b.bind(pat);
  Jacobians Ja, Jb;
  Ja.reset(pat);
  Jb.reset(pat);
  a.add_jacobians(s, Ja);
  b.add_jacobians(s, Jb);
  EXPECT_LE((Eigen::MatrixXd(Ja.Hx) - Eigen::MatrixXd(Jb.Hx)).norm(),
            1e-12 * Eigen::MatrixXd(Jb.Hx).norm());
}

TEST(ForceTerms, DampingIsProportionalToSpringStiffness) {
  // Hv of the dashpots is b_int/ks times Hx of the springs (paper eq. 30).
  const Mesh& m = test_mesh();
  const State s = random_state(m, 6, 0.05);
  SpringTerm sp(m, 2.0);
  InternalDampingTerm dp(m, 0.5);
  std::vector<std::pair<Index, Index>> pairs;
  sp.coupled_pairs(pairs);
  BlockPattern pat(m.num_nodes(), pairs);
  sp.bind(pat);
  dp.bind(pat);
  Jacobians Js, Jd;
  Js.reset(pat);
  Jd.reset(pat);
  sp.add_jacobians(s, Js);
  dp.add_jacobians(s, Jd);
  EXPECT_LE((Eigen::MatrixXd(Jd.Hv) - 0.25 * Eigen::MatrixXd(Js.Hx)).norm(),
            1e-12 * Eigen::MatrixXd(Jd.Hv).norm());
}

TEST(ForceTerms, DashpotsSumToZeroAndAreTorqueFreeAtRestLength) {
  const Mesh& m = test_mesh();
  State s = random_state(m, 12, 0.0);
  // A rigid rotation of the reference keeps every spring at rest length.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (Index i = 0; i < m.num_nodes(); ++i) s.x.segment<3>(3 * i) = R * m.ref.col(i);
  InternalDampingTerm term(m, 0.9);
  VecX f = VecX::Zero(s.x.size());
  term.add_force(s, f);
  Vec3 net = Vec3::Zero(), torque = Vec3::Zero();
  for (Index i = 0; i < m.num_nodes(); ++i) {
    net += node(f, i);
    torque += node(s.x, i).cross(node(f, i));
  }
  EXPECT_GT(f.norm(), 0.1);
  EXPECT_LE(net.norm(), 1e-12 * f.norm());
  EXPECT_LE(torque.norm(), 1e-12 * f.norm());
}

// A mesh with a triangle of the other orientation cannot share triangle normals between its
// hinges nor assemble per triangle; BendingTerm then takes the per-hinge paths, which give the
// same force and pass the finite-difference checks.
TEST(ForceTerms, BendingFallsBackToPerHingeOnAMisorientedMesh) {
  const Mesh& m = test_mesh();
  Mesh flipped = m;  // same hinges, one triangle listed clockwise
  std::swap(flipped.triangles[7][1], flipped.triangles[7][2]);
  ASSERT_TRUE(BendingTerm(m, 0.7).shares_triangle_frames());
  ASSERT_FALSE(BendingTerm(flipped, 0.7).shares_triangle_frames());
  for (unsigned seed : {1u, 2u}) {
    State s = random_state(m, seed, 0.05);
    BendingTerm a(m, 0.7), b(flipped, 0.7);
    VecX fa = VecX::Zero(s.x.size()), fb = VecX::Zero(s.x.size());
    a.add_force(s, fa);
    b.add_force(s, fb);
    EXPECT_GT(fa.norm(), 1e-3);
    EXPECT_LE((fa - fb).norm(), 1e-12 * fa.norm());
    const auto r = check_term(b, s, flipped.num_hinges());
    EXPECT_LE(r.force, kTol);
    EXPECT_LE(r.hx, kTol);
    EXPECT_LE(r.hp, kTol);
  }
  BendingTerm b(flipped, 0.7, BendingTerm::Assembly::PerTriangle);
  EXPECT_EQ(b.assembly(), BendingTerm::Assembly::PerHinge);
}
