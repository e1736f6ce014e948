// Creases summed across a band (analysis/creases/crease_band.hpp) on a square grid whose
// vertical grid lines are rows of hinges one spacing d apart: which hinges lie beside which, a
// fold spread over parallel rows counted where the hinge-by-hinge rule loses it, a fold on one
// row counted alike by both rules, and mountain and valley folds side by side kept apart.
#include "analysis/creases/crease_band.hpp"
#include "analysis/creases/crease_edges.hpp"
#include "tests/analysis/synthetic_run.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace crumple::analysis;

namespace {

constexpr int kCells = 8;
constexpr double kSide = 0.1, kD = kSide / kCells;
const double kThreshold = 2 * std::sin(18.3 * M_PI / 360);  // 18.3 degrees

double c_of(double degrees) { return 2 * std::sin(degrees * M_PI / 360); }

// p with each vertical grid line x = i d (i in `rows`) folded by `degrees` (sign = sense).
std::vector<double> rows_folded(const MeshData& m, const std::vector<std::pair<int, double>>& rows) {
  std::vector<double> p(m.hinges.size(), 0.0);
  for (const auto& [i, deg] : rows)
    for (auto h : synth::hinges_on_line(m, 0, i * kD)) p[h] = std::copysign(c_of(std::abs(deg)), deg);
  return p;
}

double length_on_line(const MeshData& m, const std::vector<char>& creased, int i) {
  double sum = 0;
  for (auto h : synth::hinges_on_line(m, 0, i * kD))
    if (creased[h]) sum += m.rest_lengths[static_cast<std::size_t>(m.hinge_edge[h])];
  return sum;
}

}  // namespace

TEST(CreaseBand, BesideMeansParallelAcrossTheBandAndOverTheEdge) {
  const MeshData m = synth::square_grid_mesh(kCells, kSide);
  const CreaseBand band(m, 2.5 * kD);  // reaches the rows one spacing away, not two
  const auto mid = synth::hinges_on_segment(m, 3 * kD, 4 * kD, 3 * kD, 5 * kD);
  ASSERT_EQ(mid.size(), 1u);
  std::vector<std::size_t> expect;
  for (int i : {2, 3, 4})
    for (auto h : synth::hinges_on_segment(m, i * kD, 4 * kD, i * kD, 5 * kD)) expect.push_back(h);
  std::sort(expect.begin(), expect.end());
  const auto& got = band.beside(mid[0]);
  ASSERT_EQ(got.size(), expect.size());
  for (std::size_t k = 0; k < got.size(); ++k) EXPECT_EQ(static_cast<std::size_t>(got[k]), expect[k]);
  EXPECT_THROW(CreaseBand(m, 0.0), std::invalid_argument);
}

TEST(CreaseBand, AFoldSpreadOverThreeRowsIsOneCrease) {
  const MeshData m = synth::square_grid_mesh(kCells, kSide);
  // 24 degrees over the rows x = 2d, 3d, 4d, 8 degrees each: below the threshold on every row.
  const auto p = rows_folded(m, {{2, 8.0}, {3, 8.0}, {4, 8.0}});
  const auto single = crease_hinges(p, kThreshold);
  for (int i : {2, 3, 4}) EXPECT_EQ(length_on_line(m, single, i), 0.0) << i;
  // A band reaching one row to each side: the middle row sums 24 degrees, each outer row only 16.
  const CreaseBand narrow(m, 2.5 * kD);
  const auto c1 = narrow.creased(p, kThreshold);
  EXPECT_NEAR(length_on_line(m, c1, 3), kSide, 1e-12);
  EXPECT_EQ(length_on_line(m, c1, 2), 0.0);
  EXPECT_EQ(length_on_line(m, c1, 4), 0.0);
  // Reaching two rows to each side: every row of the fold sums 24 degrees.
  const CreaseBand wide(m, 4.5 * kD);
  const auto c2 = wide.creased(p, kThreshold);
  for (int i : {2, 3, 4}) EXPECT_NEAR(length_on_line(m, c2, i), kSide, 1e-12) << i;
  // Nothing else is creased: the sums run over folded hinges only.
  EXPECT_NEAR(crease_length(m, c2), 3 * kSide, 1e-12);
  EXPECT_EQ(select_creases(p, kThreshold, nullptr), single);
  EXPECT_EQ(select_creases(p, kThreshold, &wide), c2);
}

TEST(CreaseBand, AFoldOnOneRowIsTheSameCreaseUnderBothRules) {
  const MeshData m = synth::square_grid_mesh(kCells, kSide);
  for (double deg : {30.0, -30.0, 10.0}) {
    const auto p = rows_folded(m, {{3, deg}});
    EXPECT_EQ(CreaseBand(m, 4.5 * kD).creased(p, kThreshold), crease_hinges(p, kThreshold)) << deg;
  }
}

TEST(CreaseBand, MountainAndValleySideBySideStayApart) {
  const MeshData m = synth::square_grid_mesh(kCells, kSide);
  // +12 and -12 degrees on neighbouring rows: no crease either way (a signed sum would cancel,
  // a sum of magnitudes would invent a 24-degree fold); +20 and -20: two creases.
  const CreaseBand band(m, 2.5 * kD);
  const auto weak = rows_folded(m, {{3, 12.0}, {4, -12.0}});
  EXPECT_EQ(crease_length(m, band.creased(weak, kThreshold)), 0.0);
  const auto strong = rows_folded(m, {{3, 20.0}, {4, -20.0}});
  const auto c = band.creased(strong, kThreshold);
  EXPECT_NEAR(length_on_line(m, c, 3), kSide, 1e-12);
  EXPECT_NEAR(length_on_line(m, c, 4), kSide, 1e-12);
}
