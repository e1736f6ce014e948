// The geometric kernels of mesh generation: Delaunay, clipped Voronoi cells and Hilbert order
// (sim/mesh/delaunay_cgal.hpp), outlines and mirrors (sim/mesh/domain.hpp), Lloyd steps
// (sim/mesh/lloyd.hpp).
#include "sim/mesh/delaunay_cgal.hpp"
#include "sim/mesh/domain.hpp"
#include "sim/mesh/lloyd.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace crumple {
namespace {

double signed_area(const std::vector<Point2>& p, const std::array<Index, 3>& t) {
  const Point2 u = p[t[1]] - p[t[0]], v = p[t[2]] - p[t[0]];
  return 0.5 * (u.x() * v.y() - u.y() * v.x());
}

std::vector<Point2> random_points_in(const Domain& d, int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(-0.5, 0.5);
  std::vector<Point2> pts;
  while (static_cast<int>(pts.size()) < count) {
    const Point2 p(U(rng), U(rng));
    if (d.contains(p, 1e-6)) pts.push_back(p);
  }
  return pts;
}

TEST(Delaunay, SquareWithCentreGivesFourCounterClockwiseTriangles) {
  const std::vector<Point2> p{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  const auto tris = delaunay_triangles(p);
  ASSERT_EQ(tris.size(), 4u);
  for (const auto& t : tris) {
    EXPECT_NEAR(signed_area(p, t), 0.25, 1e-15);
    EXPECT_NE(std::find(t.begin(), t.end(), 4), t.end());
  }
}

TEST(Delaunay, CollinearHullPointsStayVerticesWithoutFlatTriangles) {
  // Three collinear points on the bottom side of the hull (like the side nodes of a square).
  const std::vector<Point2> p{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}};
  const auto tris = delaunay_triangles(p);
  EXPECT_EQ(tris.size(), 5u);  // 2n - h - 2 with all n = 6 points used and h = 5 on the hull
  double area = 0.0;
  bool middle_used = false;
  for (const auto& t : tris) {
    EXPECT_GT(signed_area(p, t), 0.4);
    area += signed_area(p, t);
    middle_used = middle_used || std::find(t.begin(), t.end(), 1) != t.end();
  }
  EXPECT_TRUE(middle_used);
  EXPECT_NEAR(area, 4.0, 1e-15);
}

TEST(Delaunay, RejectsDuplicatePoints) {
  EXPECT_THROW(delaunay_triangles({{0, 0}, {1, 0}, {0, 1}, {1, 0}}), std::invalid_argument);
}

TEST(VoronoiCells, LoneGeneratorOwnsTheWholeClippedSquare) {
  const Domain d = Domain::square(2.0, 1);
  std::vector<Point2> g{{0.3, -0.7}};
  d.append_mirrors(g, 10.0, g);
  ASSERT_EQ(g.size(), 5u);  // the point and its image across each of the four sides
  const auto cells = voronoi_cells(g, 1);
  ASSERT_TRUE(cells[0].bounded);
  EXPECT_NEAR(cells[0].area, 4.0, 1e-12);
  EXPECT_LT(cells[0].centroid.norm(), 1e-12);
}

TEST(VoronoiCells, HullGeneratorsAreReportedUnbounded) {
  const std::vector<Point2> p{{0, 0}, {1, 0}, {0, 1}, {0.3, 0.3}};
  const auto cells = voronoi_cells(p, 4);
  EXPECT_FALSE(cells[0].bounded);
  EXPECT_TRUE(cells[3].bounded);
  EXPECT_GT(cells[3].area, 0.0);
}

// Clipped cells of random points tile the outline: their areas sum to its area, and every
// centroid is inside. Checks the mirrors for both outlines, including the angular look-up of
// the sides of a many-sided disk polygon.
TEST(VoronoiCells, MirroredCellsTileTheOutline) {
  for (const Domain& d : {Domain::square(1.0, 10), Domain::disk(1.0, 97)}) {
    const auto pts = random_points_in(d, 400, 5);
    std::vector<Point2> g = pts;
    d.append_mirrors(pts, 0.3, g);  // cells of 400 random points are far smaller than 0.3
    const auto cells = voronoi_cells(g, static_cast<Index>(pts.size()));
    double total = 0.0;
    for (const auto& c : cells) {
      ASSERT_TRUE(c.bounded);
      ASSERT_GT(d.inside_distance(c.centroid), 0.0);
      total += c.area;
    }
    EXPECT_NEAR(total, d.area(), 1e-12 * d.area());
  }
}

TEST(HilbertOrder, VisitsAGridCellByCell) {
  // On a 16 x 16 grid a Hilbert curve steps from each cell to a neighbouring one.
  std::vector<Point2> p;
  std::mt19937 rng(1);
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) p.emplace_back(i, j);
  std::shuffle(p.begin(), p.end(), rng);
  const auto order = hilbert_order(p);
  std::vector<Index> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (Index k = 0; k < static_cast<Index>(sorted.size()); ++k) ASSERT_EQ(sorted[k], k);
  for (std::size_t k = 1; k < order.size(); ++k)
    EXPECT_NEAR((p[order[k]] - p[order[k - 1]]).norm(), 1.0, 1e-12) << "step " << k;
}

TEST(Domain, SquareOutline) {
  const Domain d = Domain::square(2.0, 5);
  EXPECT_EQ(d.boundary_nodes().size(), 20u);
  EXPECT_DOUBLE_EQ(d.area(), 4.0);
  for (const auto& b : d.boundary_nodes()) EXPECT_NEAR(b.cwiseAbs().maxCoeff(), 1.0, 1e-15);
  EXPECT_NEAR(d.inside_distance({0.5, 0.0}), 0.5, 1e-15);
  EXPECT_NEAR(d.inside_distance({1.5, 0.0}), -0.5, 1e-15);
  EXPECT_TRUE(d.contains({0.9, 0.9}, 0.05));
  EXPECT_FALSE(d.contains({0.9, 0.9}, 0.2));
  const Point2 q = d.pulled_inside({1.3, -1.1}, 0.1);  // outside, beyond a corner
  EXPECT_NEAR(q.x(), 0.9, 1e-15);
  EXPECT_NEAR(q.y(), -0.9, 1e-15);
}

TEST(Domain, DiskOutlineIsTheInscribedPolygon) {
  const int n = 60;
  const Domain d = Domain::disk(2.0, n);
  EXPECT_EQ(d.boundary_nodes().size(), static_cast<std::size_t>(n));
  for (const auto& b : d.boundary_nodes()) EXPECT_NEAR(b.norm(), 1.0, 1e-15);
  EXPECT_NEAR(d.area(), 0.5 * n * std::sin(2 * std::numbers::pi / n), 1e-14);
  const double apothem = std::cos(std::numbers::pi / n);
  const Point2 q = d.pulled_inside({0.0, -1.2}, 0.01);
  EXPECT_NEAR(d.inside_distance(q), 0.01, 1e-12);
  EXPECT_NEAR(d.inside_distance({0.0, 0.0}), apothem, 1e-14);
}

TEST(Lloyd, RelaxesTowardsEqualCellsAndKeepsPointsInside) {
  const Domain d = Domain::disk(1.0, 60);
  auto pts = random_points_in(d, 250, 9);
  auto cell_area_cv = [&](const std::vector<Point2>& p) {
    std::vector<Point2> g = p;
    g.insert(g.end(), d.boundary_nodes().begin(), d.boundary_nodes().end());
    d.append_mirrors(p, 0.3, g);
    const auto cells = voronoi_cells(g, static_cast<Index>(p.size()));
    Eigen::VectorXd a(cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i) a[i] = cells[i].area;
    return std::sqrt((a.array() - a.mean()).square().mean()) / a.mean();
  };
  const double before = cell_area_cv(pts);
  const LloydStats s = lloyd_relax(d, pts, 0.055, 40);
  EXPECT_EQ(s.iterations, 40);
  // The mirrors clip every cell: none is open, no centroid lands outside.
  EXPECT_EQ(s.unbounded, 0);
  EXPECT_EQ(s.pulled_back, 0);
  for (const auto& p : pts) ASSERT_GT(d.inside_distance(p), 0.0);
  const double after = cell_area_cv(pts);
  EXPECT_LT(after, 0.3 * before);
  EXPECT_LT(s.last_max_move, 0.1 * 0.055);
}

// One step from a random start (cells of all sizes, some points near the outline) moves each
// point to the centroid of its exactly clipped cell: the same as with every point mirrored
// across every side.
TEST(Lloyd, StepUsesCellsClippedToTheOutline) {
  for (const Domain& d : {Domain::square(1.0, 18), Domain::disk(1.0, 60)}) {
    const auto start = random_points_in(d, 250, 21);
    std::vector<Point2> g = start;
    g.insert(g.end(), d.boundary_nodes().begin(), d.boundary_nodes().end());
    d.append_mirrors(start, 10.0, g);  // farther than the diameter: all sides
    const auto cells = voronoi_cells(g, static_cast<Index>(start.size()));
    auto relaxed = start;
    const LloydStats s = lloyd_relax(d, relaxed, 0.055, 1);
    EXPECT_EQ(s.unbounded, 0);
    EXPECT_EQ(s.pulled_back, 0);
    for (std::size_t i = 0; i < start.size(); ++i)
      ASSERT_LT((relaxed[i] - cells[i].centroid).norm(), 1e-12) << "point " << i;
  }
}

}  // namespace
}  // namespace crumple
