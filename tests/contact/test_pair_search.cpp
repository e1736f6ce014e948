// Grid pair search equals an O(N^2) brute force: random clouds (3D, flat, clustered with an
// outlier, degenerate) and crumpled and folded sheets with the exclusion rule; the result does
// not depend on the number of threads.
#include "sim/contact/pair_search.hpp"
#include "tests/contact/sheets.hpp"

#include <gtest/gtest.h>

#include <omp.h>
#include <random>

using namespace crumple;
using namespace crumple::testing;

namespace {

std::vector<SitePair> brute_force(const Eigen::Matrix3Xd& pos, double cutoff,
                                  const ContactSites* sites) {
  std::vector<SitePair> out;
  const Index m = static_cast<Index>(pos.cols());
  for (Index i = 0; i < m; ++i)
    for (Index j = i + 1; j < m; ++j)
      if ((pos.col(i) - pos.col(j)).norm() < cutoff && (!sites || sites->interact(i, j)))
        out.push_back({i, j});
  return out;  // sorted by (i, j) by construction
}

void expect_same(const Eigen::Matrix3Xd& pos, double cutoff, const ContactSites* sites,
                 std::size_t min_pairs) {
  const ContactPairs grid = find_pairs(pos, cutoff, sites);
  const auto ref = brute_force(pos, cutoff, sites);
  EXPECT_GE(ref.size(), min_pairs);  // the case is not vacuous
  ASSERT_EQ(grid.pairs.size(), ref.size());
  EXPECT_EQ(grid.pairs, ref);
  EXPECT_GE(grid.stats.cell, cutoff);
}

Eigen::Matrix3Xd cloud(Index m, Vec3 extent, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Eigen::Matrix3Xd p(3, m);
  for (Index i = 0; i < m; ++i) p.col(i) = Vec3(U(rng), U(rng), U(rng)).cwiseProduct(extent);
  return p;
}

}  // namespace

TEST(PairSearch, RandomCloudsMatchBruteForce) {
  expect_same(cloud(3000, Vec3(1, 1, 1), 1), 0.06, nullptr, 2000);
  expect_same(cloud(3000, Vec3(1, 2, 0), 2), 0.04, nullptr, 2000);  // flat: one cell in z
  expect_same(cloud(2000, Vec3(1, 0, 0), 3), 0.001, nullptr, 1000);  // a line
  // Cutoff larger than the box: one cell, every pair.
  expect_same(cloud(200, Vec3(1, 1, 1), 4), 5.0, nullptr, 200 * 199 / 2);
}

TEST(PairSearch, ClusteredCloudWithOutlierCapsTheGrid) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> N;
  Eigen::Matrix3Xd p(3, 3001);
  for (Index i = 0; i < 3000; ++i)
    p.col(i) = Vec3((i % 3) * 0.5, 0, 0) + 0.05 * Vec3(N(rng), N(rng), N(rng));
  p.col(3000) = Vec3(1e4, -1e4, 1e4);  // stretches the box: cells must grow, not multiply
  const ContactPairs r = find_pairs(p, 0.01, nullptr);
  const double cells = double(r.stats.dims[0]) * r.stats.dims[1] * r.stats.dims[2];
  EXPECT_LE(cells, 4.0 * 3001 + 64);
  expect_same(p, 0.01, nullptr, 500);
}

TEST(PairSearch, CoincidentPoints) {
  Eigen::Matrix3Xd p = Eigen::Matrix3Xd::Zero(3, 50);
  expect_same(p, 1e-3, nullptr, 50 * 49 / 2);
}

TEST(PairSearch, CrumpledSheetWithExclusionMatchesBruteForce) {
  const Mesh m = grid_mesh(45, 45, 1.0, 1.0, 0.2, 9);  // 2025 nodes
  const double l = m.mean_edge_length();
  const ContactSites cs = build_contact_sites(m, 1);  // about 8000 sites
  Eigen::Matrix3Xd pos;
  cs.positions(crumple_map(m, 3, 0.25), pos);
  expect_same(pos, 0.5 * l, &cs, 100);
  // Folded onto itself at a gap of 0.3 edge lengths: the layers interact across the whole fold.
  cs.positions(fold_sheet(m, 0.5, 0.3 * l), pos);
  expect_same(pos, 0.5 * l, &cs, 2000);
}

TEST(PairSearch, IndependentOfThreadCount) {
  const Mesh m = grid_mesh(40, 40, 1.0, 1.0, 0.2, 2);
  const ContactSites cs = build_contact_sites(m, 2);
  Eigen::Matrix3Xd pos;
  cs.positions(crumple_map(m, 8, 0.3), pos);
  const double cutoff = 0.4 * m.mean_edge_length();
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const ContactPairs one = find_pairs(pos, cutoff, &cs);
  omp_set_num_threads(std::max(2, saved));
  const ContactPairs many = find_pairs(pos, cutoff, &cs);
  omp_set_num_threads(saved);
  EXPECT_FALSE(one.pairs.empty());
  EXPECT_EQ(one.pairs, many.pairs);
  EXPECT_EQ(one.stats.distance_tests, many.stats.distance_tests);
}
