// The map from flat reference coordinates (simulation units) to image pixels, and the sheet's
// geometric summary (area, side length L0) used to express results in physical units.
#pragma once

#include "analysis/io/run_data.hpp"

#include <opencv2/core.hpp>

namespace crumple::analysis {

struct RasterFrame {
  double px_per_unit = 1.0;  ///< pixels per simulation length unit
  double x0 = 0.0, y0 = 0.0; ///< reference coordinates of pixel (0, 0)'s centre minus margin
  int margin = 2;            ///< empty pixels around the sheet
  int width = 0, height = 0;

  /// Pixel coordinates of reference point (x, y); image rows grow with y so the map reads
  /// like the sheet seen from +z with y downwards (the orientation does not affect any result).
  cv::Point2d to_px(double x, double y) const {
    return {margin + (x - x0) * px_per_unit, margin + (y - y0) * px_per_unit};
  }
};

/// A frame covering the mesh's bounding box at `px_per_unit`.
RasterFrame make_frame(const MeshData& mesh, double px_per_unit, int margin = 2);

/// Sheet area as the sum of reference triangle areas (simulation units squared).
double sheet_area(const MeshData& mesh);

/// L0: the larger bounding-box extent of the flat sheet (side of a square, diameter of a disk).
double sheet_size(const MeshData& mesh);

/// Mean reference triangle area (simulation units squared): the mesh's resolution floor for a
/// facet, since the smallest region a set of crease edges can enclose is one triangle.
double mean_triangle_area(const MeshData& mesh);

}  // namespace crumple::analysis
