// The contact force term: finite differences (tests/support/finite_diff.hpp) on stacked and
// folded sheets at every refinement level, zero net force and torque, no force on flat and
// rolled sheets, repulsion between layers, thread-count independence, candidate caching equal to
// a fresh search, pattern-change reporting, and use inside SheetModel.
#include "sim/contact/contact_term.hpp"
#include "sim/model/sheet_model.hpp"
#include "tests/contact/sheets.hpp"
#include "tests/support/finite_diff.hpp"

#include <gtest/gtest.h>

#include <omp.h>
#include <random>

using namespace crumple;
using namespace crumple::testing;

namespace {

State state_at(const Mesh& m, VecX x) {
  State s;
  s.x = std::move(x);
  s.v = VecX::Zero(s.x.size());
  s.p = VecX::Zero(m.num_hinges());
  return s;
}

VecX jiggle(VecX x, double amp, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N;
  for (Index k = 0; k < x.size(); ++k) x[k] += amp * N(rng);
  return x;
}

VecX force_of(const ContactTerm& t, const State& s) {
  VecX f = VecX::Zero(s.x.size());
  t.add_force(s, f);
  return f;
}

}  // namespace

TEST(ContactTerm, FiniteDifferencesOnStackedSheets) {
  const Mesh m = two_sheets(4, 1.0, 0.2, 3);
  const double l = m.mean_edge_length();
  for (int L = 0; L <= 3; ++L) {
    const double sigma = 0.8 * l;
    ContactTerm term(m, {2.0, sigma, L, 0.3});
    const State s = state_at(m, jiggle(stack_sheets(m, 1.0, 0.5 * sigma, Vec3(0.07, 0.04, 0)),
                                       0.05 * sigma, 10 + L));
    term.update(s.x);
    ASSERT_GT(term.num_active(s.x), 3) << "level " << L;
    const FdReport r = check_term(term, s, m.num_hinges(), 1e-7);
    EXPECT_GT(term.energy(s), 0.0);
    EXPECT_LT(r.force, 1e-6) << "level " << L;
    EXPECT_LT(r.hx, 1e-6) << "level " << L;
    EXPECT_LT(r.hx_asymmetry, 1e-12);
    EXPECT_EQ(r.hv_norm, 0.0);
  }
}

TEST(ContactTerm, FiniteDifferencesOnFoldedSheet) {
  const Mesh m = grid_mesh(9, 4, 1.0, 0.4, 0.2, 6);
  const double sigma = 0.6 * m.mean_edge_length();
  ContactTerm term(m, {1.0, sigma, -1, 0.3});
  EXPECT_EQ(term.settings().level, 2);  // the level-2 floor below sigma = 0.9 l
  const State s = state_at(m, jiggle(fold_sheet(m, 0.5, 0.4 * sigma), 0.03 * sigma, 4));
  term.update(s.x);
  ASSERT_GT(term.num_active(s.x), 5);
  const FdReport r = check_term(term, s, m.num_hinges(), 1e-7);
  EXPECT_LT(r.force, 1e-6);
  EXPECT_LT(r.hx, 1e-6);
}

// The term's force and energy (pair stencils flattened at the search, screened on squared
// distances) against the law applied site by site to every candidate pair, at every level.
TEST(ContactTerm, EqualsTheLawSummedOverCandidatePairs) {
  const Mesh m = grid_mesh(20, 20, 1.0, 1.0, 0.2, 8);
  const double sigma = 0.7 * m.mean_edge_length();
  for (int L = 0; L <= 3; ++L) {
    ContactTerm term(m, {1.0, sigma, L, 0.3});
    const State s = state_at(m, jiggle(fold_sheet(m, 0.5, 0.5 * sigma), 0.05 * sigma, 20 + L));
    term.update(s.x);
    ASSERT_GT(term.num_active(s.x), 10) << "level " << L;
    ASSERT_GT(term.candidates().size(), static_cast<std::size_t>(term.num_active(s.x)));
    VecX f_ref = VecX::Zero(s.x.size());
    double e_ref = 0.0;
    const ContactSites& sites = term.sites();
    auto at = [&](Index site) {
      Vec3 q = Vec3::Zero();
      for (int k = 0; k < sites.sites[site].count; ++k)
        q += sites.sites[site].weights[k] * node(s.x, sites.sites[site].nodes[k]);
      return q;
    };
    for (const SitePair& pr : term.candidates()) {
      const Vec3 r = at(pr[0]) - at(pr[1]);
      e_ref += term.law().energy(r.norm());
      const Vec3 F1 = term.law().force(r);
      for (int side = 0; side < 2; ++side) {
        const ContactSite& c = sites.sites[pr[side]];
        for (int k = 0; k < c.count; ++k)
          node(f_ref, c.nodes[k]) += (side == 0 ? c.weights[k] : -c.weights[k]) * F1;
      }
    }
    ASSERT_GT(f_ref.norm(), 0.0);
    EXPECT_LE((force_of(term, s) - f_ref).norm(), 1e-13 * f_ref.norm()) << "level " << L;
    EXPECT_NEAR(term.energy(s), e_ref, 1e-13 * e_ref) << "level " << L;
  }
}

TEST(ContactTerm, NoNetForceOrTorque) {
  const Mesh m = grid_mesh(30, 30, 1.0, 1.0, 0.2, 5);
  const double sigma = 0.5 * m.mean_edge_length();
  ContactTerm term(m, {1.0, sigma, -1, 0.3});
  for (const VecX& x : {fold_sheet(m, 0.45, 0.5 * sigma), crumple_map(m, 2, 0.3)}) {
    const State s = state_at(m, x);
    term.update(s.x);
    const VecX f = force_of(term, s);
    Vec3 sum = Vec3::Zero(), torque = Vec3::Zero();
    double scale = 0, tscale = 0;
    for (Index i = 0; i < m.num_nodes(); ++i) {
      sum += f.segment<3>(3 * i);
      torque += node(s.x, i).cross(Vec3(f.segment<3>(3 * i)));
      scale += f.segment<3>(3 * i).norm();
      tscale += node(s.x, i).norm() * f.segment<3>(3 * i).norm();
    }
    ASSERT_GT(scale, 0.0);
    EXPECT_LT(sum.norm(), 1e-13 * scale);
    EXPECT_LT(torque.norm(), 1e-13 * tscale);
  }
}

// A range well below the edge (a sheet thinner than its mesh, contact.sigma_floor 0) on sites
// refined to it: a tenth of an edge apart (level 9), the same law on each pair.
TEST(ContactTerm, FiniteDifferencesWithSitesFinerThanTheMesh) {
  const Mesh m = two_sheets(4, 1.0, 0.2, 3);
  const double sigma = 0.1 * m.mean_edge_length();
  ContactSettings cs{2.0, sigma, -1, 0.3};
  cs.max_level = kMaxContactRefinement;
  ContactTerm term(m, cs);
  EXPECT_EQ(term.sites().level, 9);
  const State s = state_at(m, jiggle(stack_sheets(m, 1.0, 0.5 * sigma, Vec3(0.07, 0.04, 0)),
                                     0.05 * sigma, 31));
  term.update(s.x);
  ASSERT_GT(term.num_active(s.x), 50);
  const FdReport r = check_term(term, s, m.num_hinges(), 1e-8);
  EXPECT_GT(term.energy(s), 0.0);
  EXPECT_LT(r.force, 1e-6);
  EXPECT_LT(r.hx, 1e-6);
  EXPECT_LT(r.hx_asymmetry, 1e-12);
}

TEST(ContactTerm, FlatAndRolledSheetsFeelNoContact) {
  const Mesh m = grid_mesh(30, 30, 1.0, 1.0, 0.2, 7);
  const double l = m.mean_edge_length();
  // Sites capped at a quarter edge (the default), or refined down to sigma.
  for (int cap : {3, kMaxContactRefinement})
    for (double ratio : {0.1, 0.2, 0.3, 0.5, 0.6, 0.8, 1.0}) {
      ContactSettings cs{1.0, ratio * l, -1, 0.3};
      cs.max_level = cap;
      ContactTerm term(m, cs);
      // Rolled over 270 degrees (R = 0.21, about 5 edge lengths) and gently (R = 0.6).
      for (const VecX& x : {m.ref_flat(), roll_sheet(m, 1.0 / (1.5 * M_PI)), roll_sheet(m, 0.6)}) {
        const State s = state_at(m, x);
        term.update(s.x);
        EXPECT_EQ(term.num_active(s.x), 0)
            << "sigma/l = " << ratio << ", level " << term.sites().level;
        EXPECT_EQ(term.energy(s), 0.0);
        EXPECT_EQ(force_of(term, s).norm(), 0.0);
      }
    }
}

TEST(ContactTerm, StackedLayersRepel) {
  const Mesh m = two_sheets(12, 1.0, 0.2, 8);
  const double sigma = 0.3 * m.mean_edge_length();
  ContactTerm term(m, {1.0, sigma, -1, 0.3});
  const Index half = m.num_nodes() / 2;
  const State s = state_at(m, stack_sheets(m, 1.0, 0.5 * sigma, Vec3(0.013, 0.021, 0)));
  term.update(s.x);
  EXPECT_GT(term.energy(s), 0.0);
  const VecX f = force_of(term, s);
  double up = 0;
  for (Index i = 0; i < m.num_nodes(); ++i) {
    // Every pair pushes the upper site up and the lower one down; weights are nonnegative.
    if (i < half) {
      EXPECT_LE(f[3 * i + 2], 0.0);
    } else {
      EXPECT_GE(f[3 * i + 2], 0.0);
      up += f[3 * i + 2];
    }
  }
  EXPECT_GT(up, 0.0);
  // Beyond the range there is nothing.
  const State far = state_at(m, stack_sheets(m, 1.0, 1.01 * sigma, Vec3(0.013, 0.021, 0)));
  term.update(far.x);
  EXPECT_EQ(term.energy(far), 0.0);
  EXPECT_EQ(force_of(term, far).norm(), 0.0);
}

TEST(ContactTerm, FoldedSheetIsPushedOpen) {
  const Mesh m = grid_mesh(30, 20, 1.0, 0.6, 0.2, 9);
  const double sigma = 0.4 * m.mean_edge_length();
  ContactTerm term(m, {1.0, sigma, -1, 0.3});
  const double gap = 0.5 * sigma;
  const State s = state_at(m, fold_sheet(m, 0.5, gap));
  term.update(s.x);
  EXPECT_GT(term.energy(s), 0.0);
  const VecX f = force_of(term, s);
  double up = 0, down = 0;
  for (Index i = 0; i < m.num_nodes(); ++i)
    (s.x[3 * i + 2] > 0.5 * gap ? up : down) += f[3 * i + 2];
  EXPECT_GT(up, 0.0);
  EXPECT_LT(down, 0.0);
}

TEST(ContactTerm, ResultsIndependentOfThreadCount) {
  const Mesh m = grid_mesh(25, 25, 1.0, 1.0, 0.2, 3);
  const double sigma = 0.5 * m.mean_edge_length();
  ContactTerm term(m, {1.0, sigma, 2, 0.3});
  const State s = state_at(m, crumple_map(m, 5, 0.3));
  term.update(s.x);
  std::vector<std::pair<Index, Index>> pairs;
  term.coupled_pairs(pairs);
  const BlockPattern pattern(m.num_nodes(), pairs);
  term.bind(pattern);
  const int saved = omp_get_max_threads();
  auto run = [&](int threads, VecX& f, Jacobians& J) {
    omp_set_num_threads(threads);
    f = force_of(term, s);
    J.reset(pattern);
    term.add_jacobians(s, J);
  };
  VecX f1, f2;
  Jacobians J1, J2;
  run(1, f1, J1);
  run(std::max(2, saved), f2, J2);
  omp_set_num_threads(saved);
  ASSERT_GT(f1.norm(), 0.0);
  EXPECT_EQ(f1, f2);
  const Eigen::Map<const VecX> v1(J1.Hx.valuePtr(), J1.Hx.nonZeros());
  const Eigen::Map<const VecX> v2(J2.Hx.valuePtr(), J2.Hx.nonZeros());
  ASSERT_GT(v1.norm(), 0.0);
  EXPECT_EQ(v1, v2);
}

// Along a trajectory of small steps, the cached candidate list (skin 0.3) gives the same forces
// as a fresh search at every step (skin 0), with far fewer searches.
TEST(ContactTerm, CandidateCachingMatchesFreshSearch) {
  const Mesh m = grid_mesh(30, 30, 1.0, 1.0, 0.2, 4);
  const double sigma = 0.5 * m.mean_edge_length();
  ContactTerm cached(m, {1.0, sigma, -1, 0.3});
  ContactTerm fresh(m, {1.0, sigma, -1, 0.0});
  const VecX x0 = fold_sheet(m, 0.5, 0.6 * sigma);
  const VecX dir = crumple_map(m, 6, 0.3) - m.ref_flat();
  for (int step = 0; step <= 40; ++step) {
    const State s = state_at(m, x0 + (0.02 * sigma * step) * dir);
    cached.update(s.x);
    fresh.update(s.x);
    EXPECT_EQ(cached.num_active(s.x), fresh.num_active(s.x));
    const VecX fc = force_of(cached, s), ff = force_of(fresh, s);
    EXPECT_LE((fc - ff).norm(), 1e-12 * std::max(ff.norm(), 1e-300)) << "step " << step;
    EXPECT_NEAR(cached.energy(s), fresh.energy(s), 1e-12 * fresh.energy(s));
  }
  EXPECT_GT(fresh.num_active(x0), 0);
  EXPECT_EQ(fresh.stats().searches, 41u);
  EXPECT_LT(cached.stats().searches, 15u);
  EXPECT_GT(cached.stats().searches, 1u);  // the motion did exceed the skin
}

TEST(ContactTerm, StaleOnceTheTwoLargestDisplacementsExceedTheSkin) {
  const Mesh m = two_sheets(6, 1.0, 0.2, 2);
  const double sigma = 0.5 * m.mean_edge_length(), skin = 0.3;
  ContactTerm term(m, {1.0, sigma, -1, skin});
  const VecX x0 = stack_sheets(m, 1.0, 0.5 * sigma);
  term.update(x0);
  const auto moved = [&](double d1, double d2) {
    VecX x = x0;
    x[0] += d1;            // node 0 along x
    x[3 * 7 + 2] -= d2;    // node 7 along z
    return x;
  };
  // One node alone may move up to the whole skin (pairs involving it change by at most that).
  EXPECT_FALSE(term.stale(moved(0.9 * skin * sigma, 0.0)));
  EXPECT_FALSE(term.stale(moved(0.6 * skin * sigma, 0.35 * skin * sigma)));
  EXPECT_TRUE(term.stale(moved(0.6 * skin * sigma, 0.45 * skin * sigma)));
  EXPECT_TRUE(term.stale(moved(1.1 * skin * sigma, 0.0)));
}

TEST(ContactTerm, UpdateReportsPatternChanges) {
  const Mesh m = two_sheets(6, 1.0, 0.2, 2);
  const double sigma = 0.5 * m.mean_edge_length();
  ContactTerm term(m, {1.0, sigma, -1, 0.3});
  const VecX apart = stack_sheets(m, 1.0, 3 * sigma), close = stack_sheets(m, 1.0, 0.5 * sigma);
  EXPECT_FALSE(term.update(apart));  // no pairs before, none now
  EXPECT_TRUE(term.candidates().empty());
  const auto v0 = term.pattern_version();
  // Within the skin but out of range: new candidates (a new pattern), the same (zero) force.
  const VecX skin = stack_sheets(m, 1.0, 1.2 * sigma);
  EXPECT_TRUE(term.stale(skin));
  EXPECT_FALSE(term.update(skin));
  EXPECT_FALSE(term.candidates().empty());
  EXPECT_EQ(term.num_active(skin), 0);
  const auto vs = term.pattern_version();
  EXPECT_NE(vs, v0);
  // In range: pairs the list lacked now push, so update() reports a changed force.
  EXPECT_TRUE(term.stale(close));
  EXPECT_TRUE(term.update(close));
  EXPECT_NE(term.pattern_version(), vs);
  EXPECT_FALSE(term.stale(close));
  EXPECT_FALSE(term.update(close));
  const auto v1 = term.pattern_version();
  EXPECT_EQ(term.pattern_version(), v1);  // asking again changes nothing
  // Apart again: the pairs in range drop out, but the old list's were the ones in range, so
  // the force with the new list is the old list's force at x (zero) and update() says so.
  EXPECT_FALSE(term.update(apart));
  EXPECT_NE(term.pattern_version(), v1);
  // Without a rebuilt pattern the Jacobian refuses to assemble instead of writing out of place.
  EXPECT_TRUE(term.update(close));
  std::vector<std::pair<Index, Index>> edges;
  for (const auto& e : m.edges) edges.emplace_back(e[0], e[1]);
  const BlockPattern mesh_only(m.num_nodes(), edges);
  EXPECT_THROW(term.bind(mesh_only), std::logic_error);
}

TEST(ContactTerm, WorksInsideSheetModel) {
  const Mesh m = two_sheets(6, 1.0, 0.2, 5);
  const double sigma = 0.5 * m.mean_edge_length();
  SheetModel model(m, ModelParams{});
  auto contact = std::make_shared<ContactTerm>(model.mesh(), ContactSettings{1.0, sigma, -1, 0.3});
  model.add_term(contact, TermKind::Contact);
  model.rebuild_pattern();
  const State s = state_at(m, stack_sheets(m, 1.0, 0.5 * sigma, Vec3(0.02, 0.01, 0)));
  Jacobians without;
  model.jacobians(s, without, false);
  ASSERT_TRUE(contact->update(s.x));
  EXPECT_TRUE(model.rebuild_pattern());
  Jacobians with;
  model.jacobians(s, with, false);
  EXPECT_GT(model.energies(s).contact, 0.0);
  // The model's Hx with contact minus the elastic part equals the contact term's own Hx.
  std::vector<std::pair<Index, Index>> pairs;
  contact->coupled_pairs(pairs);
  const BlockPattern own(m.num_nodes(), pairs);
  contact->bind(own);
  Jacobians alone;
  alone.reset(own);
  contact->add_jacobians(s, alone);
  const Eigen::MatrixXd diff = Eigen::MatrixXd(with.Hx) - Eigen::MatrixXd(without.Hx);
  ASSERT_GT(Eigen::MatrixXd(alone.Hx).norm(), 0.0);
  EXPECT_LT((diff - Eigen::MatrixXd(alone.Hx)).norm(), 1e-12 * Eigen::MatrixXd(with.Hx).norm());
}
