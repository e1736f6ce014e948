// Contact sites (Fig. 2): counts per level, one site per physical point, weights on the owning
// triangle, refinement choice, and the exclusion rule checked against its geometric definition.
#include "sim/contact/contact_sites.hpp"
#include "tests/support/grid_mesh.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>

using namespace crumple;
using crumple::testing::grid_mesh;

namespace {

const Mesh& mesh() {
  static const Mesh m = grid_mesh(9, 8, 1.0, 0.9, 0.2, 4);
  return m;
}

}  // namespace

TEST(ContactSites, CountsMatchLattice) {
  const Mesh& m = mesh();
  // Per triangle (L+2)(L+3)/2 lattice points; shared ones counted once.
  // Per edge L sites, per triangle L(L-1)/2 inside: listed for the first levels, then the formula.
  const int per_level_edge[] = {0, 1, 2, 3}, per_level_interior[] = {0, 0, 1, 3};
  for (int L : {0, 1, 2, 3, 4, 7, kMaxContactRefinement}) {
    const ContactSites cs = build_contact_sites(m, L);
    const int edge = L <= 3 ? per_level_edge[L] : L;
    const int interior = L <= 3 ? per_level_interior[L] : L * (L - 1) / 2;
    EXPECT_EQ(cs.size(), m.num_nodes() + edge * m.num_edges() + interior * m.num_triangles());
    EXPECT_EQ(cs.size(), num_contact_sites(m, L));
    int counts[4] = {0, 0, 0, 0};
    for (const auto& s : cs.sites) ++counts[s.count];
    EXPECT_EQ(counts[1], m.num_nodes());
    EXPECT_EQ(counts[2], edge * m.num_edges());
    EXPECT_EQ(counts[3], interior * m.num_triangles());
  }
  EXPECT_THROW(build_contact_sites(m, kMaxContactRefinement + 1), std::invalid_argument);
  EXPECT_THROW(build_contact_sites(m, -1), std::invalid_argument);
}

TEST(ContactSites, EachPointOnceOnTheLatticeOfItsTriangle) {
  const Mesh& m = mesh();
  for (int L : {0, 1, 2, 3, 5, 8}) {
    const ContactSites cs = build_contact_sites(m, L);
    Eigen::Matrix3Xd pos;
    cs.positions(m.ref_flat(), pos);
    std::set<std::array<long, 3>> seen;
    for (Index s = 0; s < cs.size(); ++s) {
      const ContactSite& site = cs.sites[s];
      double sum = 0;
      for (int k = 0; k < 3; ++k) {
        sum += site.weights[k];
        EXPECT_GE(site.weights[k], 0.0);
        // Weights are multiples of 1/(L+1): lattice points.
        const double q = site.weights[k] * (L + 1);
        EXPECT_NEAR(q, std::round(q), 1e-12);
        if (k >= site.count) {
          EXPECT_EQ(site.weights[k], 0.0);
        } else {
          EXPECT_GT(site.weights[k], 0.0);
        }
      }
      EXPECT_NEAR(sum, 1.0, 1e-14);
      // The three nodes are those of the owning triangle.
      auto tri = m.triangles[site.triangle];
      auto nodes = site.nodes;
      std::sort(tri.begin(), tri.end());
      std::sort(nodes.begin(), nodes.end());
      EXPECT_EQ(tri, nodes);
      const Vec3 p = pos.col(s);
      seen.insert({std::lround(p[0] * 1e9), std::lround(p[1] * 1e9), std::lround(p[2] * 1e9)});
    }
    EXPECT_EQ(static_cast<Index>(seen.size()), cs.size()) << "duplicate sites at level " << L;
  }
}

TEST(ContactSites, AutoRefinementPicksSpacingBelowRange) {
  const Mesh& m = mesh();
  const double l = m.mean_edge_length();
  bool capped = true;
  EXPECT_EQ(auto_refinement(m, 1.2 * l, &capped), 0);
  EXPECT_FALSE(capped);
  EXPECT_EQ(auto_refinement(m, l, &capped), 0);
  EXPECT_EQ(auto_refinement(m, 0.99 * l, &capped), 1);
  // Floors: below 0.9 l at least level 2 (an interior site per triangle), below 0.577 l
  // level 3 (interior sites within 0.433 l of every corner): only interior sites keep
  // triangles one edge apart from crossing.
  EXPECT_EQ(auto_refinement(m, 0.89 * l, &capped), 2);
  EXPECT_EQ(auto_refinement(m, 0.6 * l, &capped), 2);
  EXPECT_EQ(auto_refinement(m, 0.5 * l, &capped), 3);
  EXPECT_EQ(auto_refinement(m, 0.3 * l, &capped), 3);
  EXPECT_FALSE(capped);
  EXPECT_EQ(auto_refinement(m, 0.1 * l, &capped), 3);
  EXPECT_TRUE(capped);
  // A raised cap refines to the range: sites a tenth of an edge apart (level 9) for sigma = l/10,
  // the floors unchanged.
  EXPECT_EQ(auto_refinement(m, 0.1 * l, &capped, 12), 9);
  EXPECT_FALSE(capped);
  EXPECT_EQ(auto_refinement(m, 0.05 * l, &capped, 12), 12);
  EXPECT_TRUE(capped);
  EXPECT_EQ(auto_refinement(m, 0.5 * l, &capped, 12), 3);
  EXPECT_EQ(auto_refinement(m, 0.6 * l, &capped, 12), 2);
  EXPECT_EQ(auto_refinement(m, 0.05 * l, &capped, 99), kMaxContactRefinement);  // clamped cap
  EXPECT_TRUE(capped);
  // A lower cap holds even against the floors, and says so.
  EXPECT_EQ(auto_refinement(m, 0.5 * l, &capped, 1), 1);
  EXPECT_TRUE(capped);
  EXPECT_EQ(auto_refinement(m, 0.5 * l, &capped, 3), 3);
  EXPECT_FALSE(capped);
  for (double r : {1.5, 1.0, 0.7, 0.5, 0.34, 0.26}) {
    const int L = auto_refinement(m, r * l, &capped);
    EXPECT_LE(l / (L + 1), r * l * (1 + 1e-12));
    const int floor = r < 0.577 ? 3 : (r < 0.9 ? 2 : 0);
    if (L > floor) {
      EXPECT_GT(l / L, r * l);  // and it is the smallest such level (above the floors)
    }
  }
}

// The rule "sites of the same or adjacent triangles do not interact", evaluated from geometry:
// T(s) = every triangle whose closed reference region contains the site.
TEST(ContactSites, ExclusionEqualsTriangleAdjacencyRule) {
  const Mesh& m = mesh();
  for (int L : {0, 1, 2, 3, 5}) {
    const ContactSites cs = build_contact_sites(m, L);
    Eigen::Matrix3Xd pos;
    cs.positions(m.ref_flat(), pos);
    std::vector<std::vector<Index>> T(cs.size());
    for (Index s = 0; s < cs.size(); ++s)
      for (Index t = 0; t < m.num_triangles(); ++t) {
        const auto& tr = m.triangles[t];
        const Eigen::Vector2d a = m.ref.col(tr[0]).head<2>(), b = m.ref.col(tr[1]).head<2>(),
                              c = m.ref.col(tr[2]).head<2>(), p = pos.col(s).head<2>();
        Eigen::Matrix2d M;
        M << b - a, c - a;
        const Eigen::Vector2d uv = M.inverse() * (p - a);
        const double eps = 1e-9;
        if (uv[0] >= -eps && uv[1] >= -eps && uv[0] + uv[1] <= 1 + eps) T[s].push_back(t);
      }
    auto share = [&](Index t1, Index t2) {
      for (Index u : m.triangles[t1])
        for (Index v : m.triangles[t2])
          if (u == v) return true;
      return false;
    };
    std::size_t excluded = 0, checked = 0;
    for (Index s = 0; s < cs.size(); ++s)
      for (Index t = s + 1; t < cs.size(); ++t) {
        if ((pos.col(s) - pos.col(t)).norm() > 0.6) continue;  // far pairs: all interact
        bool adjacent = false;
        for (Index a : T[s])
          for (Index b : T[t]) adjacent = adjacent || share(a, b);
        ASSERT_EQ(cs.interact(s, t), !adjacent) << "level " << L << " sites " << s << " " << t;
        ASSERT_EQ(cs.interact(t, s), !adjacent);
        excluded += adjacent;
        ++checked;
      }
    EXPECT_GT(excluded, 0u);
    EXPECT_GT(checked, excluded);
  }
}
