// Facet segmentation of a crease map (docs/STATISTICS.md §1 "Facet segmentation"):
// facets are the regions of the sheet bounded by creases and the sheet border.
//
//   1. close small gaps in the crease layer (morphological closing, close_px wide); with
//      watershed_h_px > 0, also cut the regions between the creases at their necks, as the
//      experiments' automated segmentation does (neck_cuts.hpp), so that a crease broken by a gap
//      still bounds two facets;
//   2. label the sheet pixels that are not crease pixels, 4-connected
//      (cv::connectedComponentsWithStats), so 8-connected crease lines separate regions;
//   3. drop specks smaller than min_facet_px pixels (rasterisation debris at crease junctions);
//      regions touching the sheet border are kept (they are facets bounded by the border);
//   4. grow the labels over the crease and speck pixels, each taking the label of the nearest
//      facet pixel (cv::distanceTransform with per-pixel labels), so that the facets tile the
//      sheet and the crease width does not eat into facet areas (docs/STATISTICS.md §1 step 3 and
//      §3.7 step 2: "creases have zero width").
#pragma once

#include <opencv2/core.hpp>

#include <vector>

namespace crumple::analysis {

/// The closing kernel's size as applied: an odd size, so the kernel is symmetric about its
/// anchor (OpenCV neither reflects the kernel nor moves the anchor between the dilation and the
/// erosion, and with an even size the "closing" moves one-pixel crease lines by a pixel); an even
/// close_px is taken one up; 0 when close_px <= 1 disables the closing.
inline int closing_kernel_px(int close_px) { return close_px > 1 ? (close_px | 1) : 0; }

struct SegmentParams {
  /// Closing kernel size in pixels (an even size is taken one up); <= 1 disables the closing.
  int close_px = 3;
  int min_facet_px = 5;  ///< regions below this many pixels (before growth) are specks
  /// Depth in pixels of the distance-map domes that seed the neck cuts (the h of the
  /// experiments' h-maxima markers, docs/STATISTICS.md §1); 0 = no cuts, facets are the plain
  /// connected regions between the creases.
  double watershed_h_px = 0.0;
};

struct Facet {
  int label = 0;                ///< label in Segmentation::labels (1..N)
  long core_px = 0;             ///< pixels before growth over the creases
  long px = 0;                  ///< pixels after growth
  bool touches_border = false;  ///< has a pixel on the sheet outline
  double perimeter_px = 0.0;    ///< contour length after growth (outer plus holes), pixels
};

struct Segmentation {
  cv::Mat core_labels;        ///< CV_32S, facet labels before growth, 0 elsewhere
  cv::Mat labels;             ///< CV_32S, facet labels after growth, 0 outside the sheet
  std::vector<Facet> facets;  ///< facets[i].label == i + 1
  long sheet_px = 0;          ///< pixels of the sheet mask
  long crease_px = 0;         ///< sheet pixels covered by the (closed) crease layer
  long speck_px = 0;          ///< sheet pixels in dropped specks
  double outline_px = 0.0;    ///< contour length of the sheet mask, pixels
};

/// Segments `creases` (CV_8U, nonzero = crease) inside `sheet` (CV_8U, nonzero = sheet).
Segmentation segment_facets(const cv::Mat& sheet, const cv::Mat& creases,
                            const SegmentParams& params);

/// Perimeter-based crease length of docs/STATISTICS.md §2.1 in units of `size_px` (L0 in pixels):
/// P = (sum of facet perimeters - sheet outline) / (2 L0), each interior crease bordering two
/// facets. Perimeters are contour lengths through pixel centres (diagonal steps count sqrt 2).
double perimeter_crease_length(const Segmentation& seg, double size_px);

/// Facets painted in random colours from a fixed seed (same colours every run), white outside.
cv::Mat facet_image(const Segmentation& seg, unsigned seed = 12345);

}  // namespace crumple::analysis
