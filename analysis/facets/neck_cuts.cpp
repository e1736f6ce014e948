// Marker watershed on the crease distance map; see neck_cuts.hpp for what it is for.
//
// The flooding is written here rather than taken from cv::watershed because OpenCV's version
// orders its flood by the colour difference between neighbouring pixels (a gradient), whereas
// this segmentation floods the distance map itself, highest first (Meyer's algorithm on
// -distance), as the experiments' pipeline does.
#include "analysis/facets/neck_cuts.hpp"

#include <opencv2/imgproc.hpp>

#include <queue>
#include <tuple>

namespace crumple::analysis {
namespace {

/// Morphological reconstruction by dilation of `marker` under `mask` (both CV_32F, marker <=
/// mask), 8-connected, by alternating forward and backward raster scans until nothing changes
/// (Vincent's sequential algorithm: a few passes, not one per pixel of the longest path).
cv::Mat reconstruct_by_dilation(const cv::Mat& marker, const cv::Mat& mask) {
  cv::Mat j = marker.clone();
  const int rows = j.rows, cols = j.cols;
  bool changed = true;
  while (changed) {
    changed = false;
    for (int pass = 0; pass < 2; ++pass) {
      const bool fwd = pass == 0;
      for (int ri = 0; ri < rows; ++ri) {
        const int r = fwd ? ri : rows - 1 - ri;
        for (int ci = 0; ci < cols; ++ci) {
          const int c = fwd ? ci : cols - 1 - ci;
          float v = j.at<float>(r, c);
          // The already-visited half of the 8-neighbourhood of this scan direction.
          const int dr = fwd ? -1 : 1, dc = fwd ? -1 : 1;
          const int nb[4][2] = {{0, dc}, {dr, dc}, {dr, 0}, {dr, -dc}};
          for (const auto& d : nb) {
            const int rr = r + d[0], cc = c + d[1];
            if (rr < 0 || rr >= rows || cc < 0 || cc >= cols) continue;
            v = std::max(v, j.at<float>(rr, cc));
          }
          v = std::min(v, mask.at<float>(r, c));
          if (v > j.at<float>(r, c)) {
            j.at<float>(r, c) = v;
            changed = true;
          }
        }
      }
    }
  }
  return j;
}

}  // namespace

cv::Mat h_maxima(const cv::Mat& height, double h) {
  CV_Assert(height.type() == CV_32F && h > 0);
  // The h-maxima transform lowers every dome by h and lets the lowered tops spread under the
  // height: domes no deeper than h above their saddle merge into one plateau with a neighbour.
  const cv::Mat lowered = cv::max(height - static_cast<float>(h), 0.0f);
  const cv::Mat rec = reconstruct_by_dilation(lowered, height);
  // Its regional maxima: the plateaus that a reconstruction of rec - eps under rec cannot
  // raise back (every other pixel has a higher neighbour whose value flows in). One marker per
  // merged plateau, not one per original top.
  constexpr float eps = 1e-3f;
  const cv::Mat raised = reconstruct_by_dilation(rec - eps, rec);
  const cv::Mat tops = (rec - raised) > 0.5f * eps;
  return tops & (height > 0);
}

cv::Mat watershed_neck_cuts(const cv::Mat& free_in, double h_px) {
  CV_Assert(free_in.type() == CV_8U && h_px > 0);
  const cv::Mat free = free_in != 0;
  cv::Mat dist;
  cv::distanceTransform(free, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);

  cv::Mat labels;
  cv::connectedComponents(h_maxima(dist, h_px), labels, 8, CV_32S);

  // Flood from the markers, highest distance first; ties in the order pushed, so the result
  // does not depend on the heap's layout.
  using Item = std::tuple<float, long, int, int>;  // distance, -order, row, col
  std::priority_queue<Item> queue;
  long order = 0;
  const int rows = dist.rows, cols = dist.cols;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      if (labels.at<int>(r, c) > 0) queue.emplace(dist.at<float>(r, c), -order++, r, c);
  const int nb[4][2] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}};
  while (!queue.empty()) {
    const auto [d, o, r, c] = queue.top();
    queue.pop();
    const int lab = labels.at<int>(r, c);
    for (const auto& k : nb) {
      const int rr = r + k[0], cc = c + k[1];
      if (rr < 0 || rr >= rows || cc < 0 || cc >= cols) continue;
      if (!free.at<unsigned char>(rr, cc) || labels.at<int>(rr, cc) != 0) continue;
      labels.at<int>(rr, cc) = lab;
      queue.emplace(dist.at<float>(rr, cc), -order++, rr, cc);
    }
  }

  // A pixel with a 4-neighbour of a higher label becomes a cut: the cuts lie on one side of
  // every meeting line, so no pixel of one region stays 4-adjacent to another region.
  cv::Mat cuts = cv::Mat::zeros(free.size(), CV_8U);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const int lab = labels.at<int>(r, c);
      if (lab == 0) continue;
      for (const auto& k : nb) {
        const int rr = r + k[0], cc = c + k[1];
        if (rr < 0 || rr >= rows || cc < 0 || cc >= cols) continue;
        if (labels.at<int>(rr, cc) > lab) {
          cuts.at<unsigned char>(r, c) = 255;
          break;
        }
      }
    }
  return cuts;
}

}  // namespace crumple::analysis
