// Crease length, crease layer and facet segmentation of one plastic field at one threshold: the
// measurement that the per-cycle analysis makes at the chosen threshold and the sensitivity
// table repeats at others.
#pragma once

#include "analysis/creases/crease_band.hpp"
#include "analysis/facets/segment.hpp"
#include "analysis/io/run_data.hpp"
#include "analysis/raster/raster_frame.hpp"

#include <opencv2/core.hpp>

#include <vector>

namespace crumple::analysis {

/// What stays fixed across cycles and thresholds: the mesh, its raster and the sheet mask.
struct MeasureContext {
  const MeshData* mesh = nullptr;
  RasterFrame frame;
  cv::Mat sheet;     ///< sheet_mask(mesh, frame)
  double L0 = 0;     ///< sheet size in mesh length units
  double L0_px = 0;  ///< sheet size in pixels
  SegmentParams segment;
  int crease_px = 1;  ///< crease line width
  /// Creases summed across a band (creases/crease_band.hpp) when set; else hinge by hinge.
  const CreaseBand* band = nullptr;
};

struct CreaseMeasure {
  std::vector<char> creased;  ///< h flags: |p| > threshold, or the band rule
  long crease_edges = 0;
  double length = 0;       ///< plastic-edge length, mesh length units
  Segmentation seg;        ///< facets of the crease map
  double perimeter_P = 0;  ///< docs/STATISTICS.md §2.1, in L0
};

CreaseMeasure measure_creases(const MeasureContext& ctx, const std::vector<double>& p,
                              double threshold);

}  // namespace crumple::analysis
