// Facet segmentation on synthetic crease maps with known facets, which must be segmented
// exactly: a Voronoi partition, a grid and single folds.
#include "analysis/facets/segment.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <map>
#include <random>

using namespace crumple::analysis;

namespace {

cv::Mat full_sheet(int w, int h) { return cv::Mat(h, w, CV_8U, cv::Scalar(255)); }

long sum_px(const Segmentation& s, bool core) {
  long t = 0;
  for (const auto& f : s.facets) t += core ? f.core_px : f.px;
  return t;
}

/// Each true region (label image `truth`, 0 = none) must match exactly one facet, by the label
/// that covers most of it, with an area within `tol` of the true area.
void expect_matches(const cv::Mat& truth, const Segmentation& seg, int n_true, double tol) {
  ASSERT_EQ(static_cast<int>(seg.facets.size()), n_true);
  std::map<std::pair<int, int>, long> overlap;
  std::map<int, long> area;
  for (int r = 0; r < truth.rows; ++r)
    for (int c = 0; c < truth.cols; ++c) {
      const int t = truth.at<int>(r, c);
      if (t == 0) continue;
      ++area[t];
      ++overlap[{t, seg.labels.at<int>(r, c)}];
    }
  std::map<int, int> used;
  for (const auto& [t, a] : area) {
    int best = 0;
    long most = -1;
    for (const auto& [key, n] : overlap)
      if (key.first == t && n > most) most = n, best = key.second;
    ASSERT_GT(best, 0);
    EXPECT_EQ(used[best]++, 0) << "facet " << best << " matched twice";
    const double got = static_cast<double>(seg.facets[static_cast<std::size_t>(best - 1)].px);
    EXPECT_NEAR(got / static_cast<double>(a), 1.0, tol) << "region " << t;
  }
}

}  // namespace

TEST(Segment, VoronoiPartition) {
  const int W = 640, H = 560;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> ux(0, W), uy(0, H);
  std::vector<cv::Point2d> seeds;
  while (seeds.size() < 18) {  // keep seeds apart so every cell is many pixels wide
    const cv::Point2d p(ux(rng), uy(rng));
    bool ok = true;
    for (const auto& q : seeds) ok = ok && cv::norm(p - q) > 90;
    if (ok) seeds.push_back(p);
  }
  cv::Mat truth(H, W, CV_32S);
  for (int r = 0; r < H; ++r)
    for (int c = 0; c < W; ++c) {
      int best = 0;
      for (std::size_t k = 1; k < seeds.size(); ++k)
        if (cv::norm(cv::Point2d(c, r) - seeds[k]) < cv::norm(cv::Point2d(c, r) - seeds[best]))
          best = static_cast<int>(k);
      truth.at<int>(r, c) = best + 1;
    }
  // Cell boundaries: a pixel whose right or lower neighbour lies in another cell.
  cv::Mat creases = cv::Mat::zeros(H, W, CV_8U);
  for (int r = 0; r < H; ++r)
    for (int c = 0; c < W; ++c)
      if ((c + 1 < W && truth.at<int>(r, c + 1) != truth.at<int>(r, c)) ||
          (r + 1 < H && truth.at<int>(r + 1, c) != truth.at<int>(r, c)))
        creases.at<unsigned char>(r, c) = 255;
  const cv::Mat sheet = full_sheet(W, H);
  const Segmentation seg = segment_facets(sheet, creases, {3, 5});
  expect_matches(truth, seg, static_cast<int>(seeds.size()), 0.02);
  EXPECT_EQ(sum_px(seg, true), seg.sheet_px - seg.crease_px - seg.speck_px);
  EXPECT_EQ(seg.speck_px, 0);
  EXPECT_EQ(sum_px(seg, false), seg.sheet_px);
  EXPECT_EQ(cv::countNonZero(seg.labels == 0), 0);
}

TEST(Segment, GridWithSpeckAndPerimeterLength) {
  // 5 x 4 cells of 100 x 100 pixels separated by 1-pixel crease lines. With zero-width creases
  // along the line centres a cell also owns half of each neighbouring line: that is the truth.
  const int cell = 100, nx = 5, ny = 4, W = nx * cell + nx - 1, H = ny * cell + ny - 1;
  cv::Mat creases = cv::Mat::zeros(H, W, CV_8U);
  for (int i = 1; i < nx; ++i) cv::line(creases, {i * (cell + 1) - 1, 0}, {i * (cell + 1) - 1, H - 1}, 255, 1);
  for (int j = 1; j < ny; ++j) cv::line(creases, {0, j * (cell + 1) - 1}, {W - 1, j * (cell + 1) - 1}, 255, 1);
  // A closed 4x4 outline inside one cell encloses a 2x2 speck: dropped, then grown over.
  cv::rectangle(creases, cv::Rect(40, 40, 4, 4), 255, 1);
  const cv::Mat sheet = full_sheet(W, H);
  const Segmentation seg = segment_facets(sheet, creases, {1, 5});
  ASSERT_EQ(seg.facets.size(), static_cast<std::size_t>(nx * ny));
  EXPECT_EQ(seg.speck_px, 4);
  EXPECT_EQ(sum_px(seg, true), seg.sheet_px - seg.crease_px - seg.speck_px);
  EXPECT_EQ(sum_px(seg, false), seg.sheet_px);
  int border = 0;
  for (const auto& f : seg.facets) {
    // Which cell: from the centre of the facet's core pixels.
    const cv::Moments mo = cv::moments(seg.core_labels == f.label, true);
    const int i = static_cast<int>(mo.m10 / mo.m00) / (cell + 1);
    const int j = static_cast<int>(mo.m01 / mo.m00) / (cell + 1);
    const double w = cell + 0.5 * ((i > 0) + (i < nx - 1)), h = cell + 0.5 * ((j > 0) + (j < ny - 1));
    EXPECT_NEAR(static_cast<double>(f.px) / (w * h), 1.0, 0.02) << i << " " << j;
    border += f.touches_border;
  }
  EXPECT_EQ(border, 14);  // all but the 3 x 2 inner cells
  // Interior crease length: 4 vertical lines of H and 3 horizontal of W, in units of W. The
  // speck's outline is grown over and belongs to no facet boundary afterwards.
  const double expected = ((nx - 1.0) * H + (ny - 1.0) * W) / W;
  EXPECT_NEAR(perimeter_crease_length(seg, W) / expected, 1.0, 0.03);
}

TEST(Segment, SingleFolds) {
  const int W = 400, H = 400;
  const cv::Mat sheet = full_sheet(W, H);
  {  // diagonal fold: two right triangles of half the sheet each
    cv::Mat creases = cv::Mat::zeros(H, W, CV_8U);
    cv::line(creases, {0, 0}, {W - 1, H - 1}, 255, 1);
    const Segmentation seg = segment_facets(sheet, creases, {3, 5});
    ASSERT_EQ(seg.facets.size(), 2u);
    for (const auto& f : seg.facets) EXPECT_NEAR(f.px / (0.5 * W * H), 1.0, 0.02);
    EXPECT_NEAR(perimeter_crease_length(seg, W), std::sqrt(2.0), 0.05);
  }
  {  // off-centre straight fold at 30 % of the width
    cv::Mat creases = cv::Mat::zeros(H, W, CV_8U);
    cv::line(creases, {120, 0}, {120, H - 1}, 255, 2);
    const Segmentation seg = segment_facets(sheet, creases, {3, 5});
    ASSERT_EQ(seg.facets.size(), 2u);
    std::vector<double> a{static_cast<double>(seg.facets[0].px), static_cast<double>(seg.facets[1].px)};
    std::sort(a.begin(), a.end());
    EXPECT_NEAR(a[0] / (0.3 * W * H), 1.0, 0.02);
    EXPECT_NEAR(a[1] / (0.7 * W * H), 1.0, 0.02);
  }
}

TEST(Segment, RoundSheetKeepsOutsideUnlabelled) {
  cv::Mat sheet = cv::Mat::zeros(300, 300, CV_8U);
  cv::circle(sheet, {150, 150}, 140, 255, cv::FILLED);
  cv::Mat creases = cv::Mat::zeros(300, 300, CV_8U);
  cv::line(creases, {0, 150}, {299, 150}, 255, 1);
  const Segmentation seg = segment_facets(sheet, creases, {3, 5});
  ASSERT_EQ(seg.facets.size(), 2u);
  EXPECT_EQ(sum_px(seg, false), seg.sheet_px);
  EXPECT_EQ(cv::countNonZero(seg.labels != 0), cv::countNonZero(sheet));
  EXPECT_TRUE(seg.facets[0].touches_border && seg.facets[1].touches_border);
}

// The closing keeps every crease line where it is whatever its kernel size: a one-pixel line
// from one edge of the sheet to the other still separates two facets at even and odd sizes
// (OpenCV does not reflect the kernel, so an even, off-centre kernel moves the line by a pixel
// and opens a gap at the sheet's edge), and two lines closer than the kernel merge into one.
TEST(Segment, ClosingKeepsThinLinesAtEvenAndOddSizes) {
  cv::Mat sheet = cv::Mat::zeros(220, 220, CV_8U);
  cv::rectangle(sheet, cv::Rect(10, 10, 200, 200), cv::Scalar(255), cv::FILLED);
  cv::Mat creases = cv::Mat::zeros(220, 220, CV_8U);
  cv::line(creases, {100, 10}, {100, 209}, cv::Scalar(255), 1);
  cv::line(creases, {10, 60}, {209, 60}, cv::Scalar(255), 1);
  for (int size : {2, 3, 4, 5, 12, 24, 25}) {
    SegmentParams p;
    p.close_px = size;
    EXPECT_EQ(segment_facets(sheet, creases, p).facets.size(), 4u) << "close_px " << size;
  }
  cv::line(creases, {110, 10}, {110, 209}, cv::Scalar(255), 1);
  SegmentParams narrow, wide;
  narrow.close_px = 4;
  wide.close_px = 24;
  EXPECT_EQ(segment_facets(sheet, creases, narrow).facets.size(), 6u);
  EXPECT_EQ(segment_facets(sheet, creases, wide).facets.size(), 4u);
}
