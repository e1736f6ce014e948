// The whole per-run analysis of crumple-analyze (DESIGN.md §8), in memory: for each cycle the
// crease length (plastic-edge length and the perimeter-based P of statistics.md §2.1), the crease
// map, the facets and their scaled-area statistics (statistics.md §3.7), and over the cycles the
// fit of the logarithmic law (statistics.md §2.3). Nothing is written here (run/write_results).
#pragma once

#include "analysis/creases/crease_edges.hpp"
#include "analysis/facets/area_distribution.hpp"
#include "analysis/facets/segment.hpp"
#include "analysis/fits/log_law.hpp"
#include "analysis/io/run_data.hpp"

#include <opencv2/core.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace crumple::analysis {

struct AnalyzeOptions {
  double threshold = kDefaultCreaseThreshold;  ///< crease when |p| > threshold
  double px_per_cm = 40.0;                     ///< raster resolution
  SegmentParams segment;                       ///< closing size, minimum facet pixels
  int crease_px = 1;                           ///< crease line width in pixels
  int bootstrap = 200;                         ///< resamples for the a interval and KS p-value
  std::uint64_t seed = 1;                      ///< seed of the resampling
};

struct FacetRecord {
  int id = 0;
  double area_m2 = 0, x = 0, xi = 0;  ///< physical area, fraction of the sheet, x / mean x
  bool touches_border = false;
};

/// Shape statistics of one cycle's facets (statistics.md §3.3-3.4, §3.7).
struct ShapeStats {
  double a_fit = 0, a_fit_lo = 0, a_fit_hi = 0;  ///< MLE and its bootstrap 95 % interval
  double a_moment = 0;                           ///< NaN when the variance vanishes
  double a_univ = 0;                             ///< root of (a+1)/a^3 = tau^2 s
  double ks = 0, ks_p = 0;                       ///< KS distance to phi(.; a_fit), bootstrap p
  double ks_univ = 0;                            ///< KS distance to phi(.; a_univ)
};

struct CycleResult {
  int cycle = 0;
  long crease_edges = 0, new_crease_edges = 0;
  double crease_length_m = 0, crease_length_L0 = 0;
  double new_crease_length_m = 0, new_crease_length_L0 = 0;
  double perimeter_P = 0;  ///< statistics.md §2.1, in L0
  std::vector<FacetRecord> facets;
  double mean_x = 0, mean_area_m2 = 0;
  long sheet_px = 0, crease_px = 0, speck_px = 0;
  std::optional<ShapeStats> shape;  ///< absent with fewer than 2 facets
  std::vector<DensityBin> distribution;
  cv::Mat crease_image, facet_image;
};

struct RunAnalysis {
  double L0_m = 0, area_m2 = 0, px_per_m = 0;
  int image_width = 0, image_height = 0;
  double mean_triangle_area_m2 = 0;  ///< the mesh floor: creases cannot enclose less
  double pixel_floor_m2 = 0;         ///< min_facet_px pixels
  double smallest_resolvable_m2 = 0; ///< the larger of the two floors
  std::optional<double> compaction;
  std::vector<CycleResult> cycles;
  std::optional<LogLawFit> fit_length, fit_P;  ///< on l/L0 and on P against n
  std::string fit_note;                        ///< why a fit is missing, if it is
  std::vector<std::string> warnings;
};

RunAnalysis analyze_run(const RunData& run, const AnalyzeOptions& opt);

}  // namespace crumple::analysis
