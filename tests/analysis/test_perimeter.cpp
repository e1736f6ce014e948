// The perimeter length P (docs/STATISTICS.md §2.1) on a crease map with a known answer: a closed
// crease loop and a crease right across the sheet bound three facets, and dangling segments
// (isolated, or attached to a crease at one end only) separate no two facets, so they count in
// the plastic-edge length l but not in P. Run through the whole per-run analysis (mesh, raster,
// segmentation) on a run held in memory.
#include "analysis/run/analyze_run.hpp"
#include "tests/analysis/synthetic_run.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace crumple::analysis;

namespace {

struct Segment {
  double ax, ay, bx, by;
  double length() const { return std::hypot(bx - ax, by - ay); }
};

CycleResult analyse(const MeshData& m, const std::vector<Segment>& creases) {
  std::vector<double> p(m.hinges.size(), 0.0);
  for (const auto& s : creases)
    for (auto h : synth::hinges_on_segment(m, s.ax, s.ay, s.bx, s.by)) p[h] = 0.8;
  RunData run;
  run.path = "memory";
  run.mesh = m;
  run.cycles.push_back({1, p});
  AnalyzeOptions opt;
  opt.bootstrap = 10;
  opt.threshold = 0.1;
  return analyze_run(run, opt).cycles.at(0);
}

}  // namespace

TEST(PerimeterLength, DanglingSegmentsDoNotCount) {
  // 10 cm sheet, 5 mm grid, 40 px/cm: L0 = 400 px.
  const double L0 = 0.1;
  const MeshData m = synth::square_grid_mesh(20, L0);
  const std::vector<Segment> bounding = {
      {0.025, 0.025, 0.075, 0.025}, {0.075, 0.025, 0.075, 0.075},  // closed square loop,
      {0.075, 0.075, 0.025, 0.075}, {0.025, 0.075, 0.025, 0.025},  // side 5 cm
      {0.0, 0.015, 0.1, 0.015}};                                   // across the sheet
  const std::vector<Segment> dangling = {
      {0.09, 0.03, 0.09, 0.07},      // isolated, in the outer facet
      {0.075, 0.05, 0.085, 0.05},    // spur on the loop
      {0.05, 0.035, 0.05, 0.065},    // isolated, inside the loop
      {0.01, 0.015, 0.01, 0.05},     // spur on the crossing crease
      {0.03, 0.08, 0.045, 0.095}};   // diagonal, isolated
  double bounding_len = 0, dangling_len = 0;
  for (const auto& s : bounding) bounding_len += s.length();
  for (const auto& s : dangling) dangling_len += s.length();
  const double P_true = bounding_len / L0;  // 3 L0: each bounding crease borders two facets

  std::vector<Segment> all = bounding;
  all.insert(all.end(), dangling.begin(), dangling.end());
  const CycleResult with = analyse(m, all);
  const CycleResult without = analyse(m, bounding);

  // l is exact: the sum of the crease edges' rest lengths.
  EXPECT_NEAR(with.crease_length_L0, (bounding_len + dangling_len) / L0, 1e-12);
  EXPECT_NEAR(without.crease_length_L0, P_true, 1e-12);
  EXPECT_EQ(with.facets.size(), 3u);  // inside the loop, around it, the strip below the crossing
  EXPECT_EQ(without.facets.size(), 3u);
  // Tolerance of P against the analytic value: contours are traced through pixel centres, half
  // a pixel inside each facet's true boundary, so each of the 3 facet contours and the sheet
  // outline (subtracted) is short by about 4 px and the hole contour of the ring long by about
  // 4 px; the spurs' junctions add a notch of a pixel or so each. That is at most ~24 px of
  // summed perimeter, ~12 px of P L0: 12 / 400 = 0.03 L0, 1 % of P.
  const double tol = 0.03;
  std::printf("P with dangling segments %.4f, without %.4f, analytic %.4f; l/L0 %.4f\n",
              with.perimeter_P, without.perimeter_P, P_true, with.crease_length_L0);
  EXPECT_NEAR(without.perimeter_P, P_true, tol);
  EXPECT_NEAR(with.perimeter_P, P_true, tol);
  // The dangling segments move P by the junction pixels only, not by their 1.36 L0.
  EXPECT_NEAR(with.perimeter_P, without.perimeter_P, 4.0 / 400);
  ASSERT_TRUE(with.dangling_fraction.has_value());
  EXPECT_DOUBLE_EQ(*with.dangling_fraction, 1.0 - with.perimeter_P / with.crease_length_L0);
  EXPECT_NEAR(*with.dangling_fraction, dangling_len / (bounding_len + dangling_len), tol / 4);
  ASSERT_TRUE(without.dangling_fraction.has_value());
  EXPECT_NEAR(*without.dangling_fraction, 0.0, tol / 3);
}

TEST(PerimeterLength, NoCreasesNoDanglingFraction) {
  const MeshData m = synth::square_grid_mesh(6, 0.1);
  const CycleResult c = analyse(m, {});
  EXPECT_EQ(c.crease_length_L0, 0.0);
  EXPECT_FALSE(c.dangling_fraction.has_value());
  EXPECT_EQ(c.facets.size(), 1u);
  EXPECT_NEAR(c.perimeter_P, 0.0, 1e-12);
}

TEST(SingleTriangleFacets, CountedAgainstTheMeanTriangle) {
  // A 4 x 4 grid of 2.5 cm cells, two triangles each. Creasing the diagonal y = x and the lines
  // x = 0.025, y = 0.025 cuts the corner cell into two single triangles; the two strips and the
  // two halves of the remaining 7.5 cm square are larger.
  const MeshData m = synth::square_grid_mesh(4, 0.1);
  const CycleResult c = analyse(m, {{0.0, 0.0, 0.1, 0.1}, {0.025, 0.0, 0.025, 0.1},
                                    {0.0, 0.025, 0.1, 0.025}});
  ASSERT_EQ(c.facets.size(), 6u);
  EXPECT_EQ(c.n_single_triangle_facets, 2);
  ASSERT_TRUE(c.single_triangle_fraction.has_value());
  EXPECT_DOUBLE_EQ(*c.single_triangle_fraction, 2.0 / 6.0);
}
