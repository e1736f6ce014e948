// The neck cuts of the facet segmentation (analysis/facets/neck_cuts.hpp): h-maxima on known
// height fields, cuts across a dumbbell's neck and none in a convex region, and a crease broken
// by a gap that still bounds two facets once the cuts are on.
#include "analysis/facets/neck_cuts.hpp"
#include "analysis/facets/segment.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <cmath>

using namespace crumple::analysis;

namespace {

int components(const cv::Mat& mask) {
  cv::Mat lab;
  return cv::connectedComponents(mask != 0, lab, 8, CV_32S) - 1;
}

/// Two Gaussian domes of heights a and b, 60 px apart, on a 40 x 120 strip.
cv::Mat two_domes(float a, float b) {
  cv::Mat f(40, 120, CV_32F);
  for (int r = 0; r < f.rows; ++r)
    for (int c = 0; c < f.cols; ++c) {
      const auto g = [&](int c0) {
        return std::exp(-((c - c0) * (c - c0) + (r - 20) * (r - 20)) / (2.0f * 15.0f * 15.0f));
      };
      f.at<float>(r, c) = 1.0f + a * g(30) + b * g(90);
    }
  return f;
}

/// Two 60 x 60 squares joined by a corridor `neck` pixels wide and 30 long, inside a frame.
cv::Mat dumbbell(int neck) {
  cv::Mat free = cv::Mat::zeros(100, 170, CV_8U);
  cv::rectangle(free, cv::Rect(10, 20, 60, 60), 255, cv::FILLED);
  cv::rectangle(free, cv::Rect(100, 20, 60, 60), 255, cv::FILLED);
  cv::rectangle(free, cv::Rect(70, 50 - neck / 2, 30, neck), 255, cv::FILLED);
  return free;
}

}  // namespace

TEST(NeckCuts, HMaximaCountsDomesDeeperThanH) {
  // Heights 10 and 10 with a saddle 2.7 above the base: each dome rises 7.3 above it.
  const cv::Mat f = two_domes(10.0f, 10.0f);
  const float saddle = f.at<float>(20, 60);
  const float depth = f.at<float>(20, 30) - saddle;
  ASSERT_GT(depth, 6.0f);
  ASSERT_LT(depth, 8.0f);
  EXPECT_EQ(components(h_maxima(f, 2.0)), 2);
  EXPECT_EQ(components(h_maxima(f, 9.0)), 1);  // the two shallow tops merge into one plateau
  // A dome and a bump of 1 on its flank: the bump is no maximum at h = 2, is one at h = 0.5.
  const cv::Mat g = two_domes(10.0f, 1.0f);
  EXPECT_EQ(components(h_maxima(g, 2.0)), 1);
  EXPECT_EQ(components(h_maxima(g, 0.05)), 2);
}

TEST(NeckCuts, CutsADumbbellAtItsNeckOnly) {
  const cv::Mat free = dumbbell(8);
  ASSERT_EQ(components(free), 1);
  const cv::Mat cuts = watershed_neck_cuts(free, 4.0);
  ASSERT_GT(cv::countNonZero(cuts), 0);
  // The cut lies in the corridor, spans it, and leaves two regions under 4-connectivity.
  cv::Mat outside = cuts.clone();
  outside(cv::Rect(70, 0, 30, 100)) = 0;
  EXPECT_EQ(cv::countNonZero(outside), 0);
  EXPECT_LE(cv::countNonZero(cuts), 8 + 2);
  cv::Mat lab;
  EXPECT_EQ(cv::connectedComponents(free & ~cuts, lab, 4, CV_32S) - 1, 2);
  EXPECT_NE(lab.at<int>(50, 40), lab.at<int>(50, 130));
  // A neck nearly as wide as the squares is no neck at this depth: no cut.
  EXPECT_EQ(cv::countNonZero(watershed_neck_cuts(dumbbell(56), 4.0)), 0);
}

TEST(NeckCuts, LeavesConvexRegionsWhole) {
  cv::Mat free = cv::Mat::zeros(200, 300, CV_8U);
  cv::rectangle(free, cv::Rect(5, 5, 290, 190), 255, cv::FILLED);
  EXPECT_EQ(cv::countNonZero(watershed_neck_cuts(free, 4.0)), 0);
  cv::Mat disc = cv::Mat::zeros(200, 200, CV_8U);
  cv::circle(disc, {100, 100}, 90, 255, cv::FILLED);
  EXPECT_EQ(cv::countNonZero(watershed_neck_cuts(disc, 4.0)), 0);
}

TEST(NeckCuts, BrokenCreaseStillBoundsTwoFacets) {
  // A vertical crease through a 300 x 200 sheet with a 12-pixel gap in the middle: too wide for
  // the 3-pixel closing, so plain components see one facet; the cuts close it.
  const int W = 300, H = 200;
  const cv::Mat sheet(H, W, CV_8U, cv::Scalar(255));
  cv::Mat creases = cv::Mat::zeros(H, W, CV_8U);
  cv::line(creases, {150, 0}, {150, 93}, 255, 1);
  cv::line(creases, {150, 106}, {150, H - 1}, 255, 1);
  SegmentParams plain{3, 5};
  EXPECT_EQ(segment_facets(sheet, creases, plain).facets.size(), 1u);
  SegmentParams cut{3, 5, 4.0};
  const Segmentation seg = segment_facets(sheet, creases, cut);
  ASSERT_EQ(seg.facets.size(), 2u);
  for (const auto& f : seg.facets) EXPECT_NEAR(f.px / (0.5 * W * H), 1.0, 0.03);
  // P counts the crease with its bridged gap: one line of the sheet's height, in units of W.
  EXPECT_NEAR(perimeter_crease_length(seg, W) / (static_cast<double>(H) / W), 1.0, 0.05);
}
