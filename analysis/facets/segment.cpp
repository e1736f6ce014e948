// Facet segmentation with OpenCV; see segment.hpp for the steps.
#include "analysis/facets/segment.hpp"

#include "analysis/facets/neck_cuts.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>

namespace crumple::analysis {
namespace {

/// Contour length of the nonzero pixels of `bin` (outer boundaries and holes).
double contour_length(const cv::Mat& bin) {
  // One empty pixel around the region so contours touching the ROI edge are traced fully.
  cv::Mat padded;
  cv::copyMakeBorder(bin, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(padded, contours, cv::RETR_CCOMP, cv::CHAIN_APPROX_NONE);
  double len = 0.0;
  for (const auto& c : contours) len += cv::arcLength(c, true);
  return len;
}

/// Assigns every sheet pixel without a label the label of the nearest labelled pixel.
cv::Mat grow_labels(const cv::Mat& core, const cv::Mat& sheet) {
  cv::Mat grown = core.clone();
  // distanceTransform measures the distance to the nearest zero pixel of its input and, with
  // DIST_LABEL_PIXEL, numbers the zero pixels 1, 2, ... in raster order; lut maps that number
  // back to the facet label of the pixel.
  cv::Mat src = (core == 0);
  std::vector<int> lut(1, 0);
  for (int r = 0; r < core.rows; ++r) {
    const int* c = core.ptr<int>(r);
    for (int j = 0; j < core.cols; ++j)
      if (c[j] != 0) lut.push_back(c[j]);
  }
  if (lut.size() == 1) return grown;
  cv::Mat dist, nearest;
  cv::distanceTransform(src, dist, nearest, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
  for (int r = 0; r < core.rows; ++r) {
    int* g = grown.ptr<int>(r);
    const int* n = nearest.ptr<int>(r);
    const unsigned char* s = sheet.ptr<unsigned char>(r);
    for (int j = 0; j < core.cols; ++j)
      if (s[j] && g[j] == 0) g[j] = lut[static_cast<std::size_t>(n[j])];
  }
  return grown;
}

}  // namespace

Segmentation segment_facets(const cv::Mat& sheet_in, const cv::Mat& creases_in,
                            const SegmentParams& params) {
  CV_Assert(sheet_in.type() == CV_8U && creases_in.type() == CV_8U &&
            sheet_in.size() == creases_in.size());
  Segmentation seg;
  const cv::Mat sheet = sheet_in != 0;
  cv::Mat creases = creases_in != 0;
  if (const int size = closing_kernel_px(params.close_px); size > 0) {
    const cv::Mat k = cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(size, size));
    cv::morphologyEx(creases, creases, cv::MORPH_CLOSE, k);
  }
  creases &= sheet;
  if (params.watershed_h_px > 0) creases |= watershed_neck_cuts(sheet & ~creases, params.watershed_h_px);
  seg.sheet_px = cv::countNonZero(sheet);
  seg.crease_px = cv::countNonZero(creases);
  const cv::Mat free = sheet & ~creases;

  cv::Mat comp, stats, centroids;
  const int n = cv::connectedComponentsWithStats(free, comp, stats, centroids, 4, CV_32S);
  std::vector<int> relabel(static_cast<std::size_t>(n), 0);
  int next = 0;
  for (int i = 1; i < n; ++i) {
    const int area = stats.at<int>(i, cv::CC_STAT_AREA);
    if (area >= params.min_facet_px) {
      relabel[static_cast<std::size_t>(i)] = ++next;
      Facet f;
      f.label = next;
      f.core_px = area;
      seg.facets.push_back(f);
    } else {
      seg.speck_px += area;
    }
  }
  seg.core_labels = cv::Mat::zeros(comp.size(), CV_32S);
  for (int r = 0; r < comp.rows; ++r) {
    const int* c = comp.ptr<int>(r);
    int* o = seg.core_labels.ptr<int>(r);
    for (int j = 0; j < comp.cols; ++j) o[j] = relabel[static_cast<std::size_t>(c[j])];
  }
  seg.labels = grow_labels(seg.core_labels, sheet);

  // Areas, bounding boxes and border contact after growth.
  cv::Mat inner;
  cv::erode(sheet, inner, cv::Mat::ones(3, 3, CV_8U), cv::Point(-1, -1), 1, cv::BORDER_CONSTANT,
            cv::Scalar(0));
  const cv::Mat ring = sheet & ~inner;
  std::vector<cv::Rect> box(seg.facets.size());
  for (int r = 0; r < seg.labels.rows; ++r) {
    const int* l = seg.labels.ptr<int>(r);
    const unsigned char* b = ring.ptr<unsigned char>(r);
    for (int j = 0; j < seg.labels.cols; ++j) {
      if (l[j] == 0) continue;
      Facet& f = seg.facets[static_cast<std::size_t>(l[j] - 1)];
      cv::Rect& bb = box[static_cast<std::size_t>(l[j] - 1)];
      bb = f.px == 0 ? cv::Rect(j, r, 1, 1) : (bb | cv::Rect(j, r, 1, 1));
      ++f.px;
      if (b[j]) f.touches_border = true;
    }
  }
  for (std::size_t i = 0; i < seg.facets.size(); ++i)
    seg.facets[i].perimeter_px = contour_length(seg.labels(box[i]) == seg.facets[i].label);
  seg.outline_px = contour_length(sheet);
  return seg;
}

double perimeter_crease_length(const Segmentation& seg, double size_px) {
  double sum = 0.0;
  for (const auto& f : seg.facets) sum += f.perimeter_px;
  return (sum - seg.outline_px) / (2.0 * size_px);
}

cv::Mat facet_image(const Segmentation& seg, unsigned seed) {
  cv::RNG rng(seed);
  std::vector<cv::Vec3b> colour(seg.facets.size() + 1, cv::Vec3b(255, 255, 255));
  for (std::size_t i = 1; i < colour.size(); ++i)
    colour[i] = cv::Vec3b(static_cast<unsigned char>(rng.uniform(40, 230)),
                          static_cast<unsigned char>(rng.uniform(40, 230)),
                          static_cast<unsigned char>(rng.uniform(40, 230)));
  cv::Mat img(seg.labels.size(), CV_8UC3);
  for (int r = 0; r < img.rows; ++r) {
    const int* l = seg.labels.ptr<int>(r);
    auto* o = img.ptr<cv::Vec3b>(r);
    for (int j = 0; j < img.cols; ++j) o[j] = colour[static_cast<std::size_t>(l[j])];
  }
  return img;
}

}  // namespace crumple::analysis
