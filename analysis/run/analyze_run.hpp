// The whole per-run analysis of crumple-analyze, in memory: for each cycle the crease length
// (plastic-edge length and the perimeter-based P of docs/STATISTICS.md §2.1) with its dangling
// part, the per-stage accounting of the new creases (creases/stage_accounting.hpp), the crease
// map, the facets and their scaled-area statistics (docs/STATISTICS.md §3.7); over the cycles
// the fits of the logarithmic law to the cumulative values and to the per-cycle increments
// (docs/STATISTICS.md §2.3) and the threshold sensitivity table. The crease threshold follows
// creases/threshold_rule.hpp. Nothing is written here (run/write_results).
#pragma once

#include "analysis/creases/crease_edges.hpp"
#include "analysis/creases/stage_accounting.hpp"
#include "analysis/creases/threshold_rule.hpp"
#include "analysis/facets/area_distribution.hpp"
#include "analysis/facets/segment.hpp"
#include "analysis/fits/log_law.hpp"
#include "analysis/fits/truncated_shape.hpp"
#include "analysis/io/run_data.hpp"
#include "analysis/run/threshold_sensitivity.hpp"

#include <opencv2/core.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace crumple::analysis {

struct AnalyzeOptions {
  /// Absolute crease threshold (--threshold); when absent the threshold is threshold_c0 x c0.
  std::optional<double> threshold;
  double threshold_c0 = kDefaultThresholdFactor;  ///< F in crease when |p| > F c0
  /// Crease angle in degrees (--crease-angle): |p| > 2 sin(angle / 2), as output.crease_angle.
  std::optional<double> crease_angle;
  /// --threshold-c0 was given: F c0 even where the run's /config states output.crease_angle.
  bool threshold_c0_given = false;
  double px_per_cm = 40.0;                        ///< raster resolution
  /// When > 0 (--px-per-edge), the raster follows the mesh instead: px_per_cm is set so that
  /// the mean mesh edge spans this many pixels, so that a ladder in node count measures every
  /// rung at the same resolution relative to its triangles (docs/studies/convergence_radius/).
  double px_per_edge = 0.0;
  SegmentParams segment;                          ///< closing size, minimum facet pixels
  /// When > 0 (--close-mm), the closing kernel is this many millimetres of the flat sheet
  /// instead of segment.close_px pixels: crease lines closer than that merge into one and the
  /// facets between them vanish, at the same physical scale on every mesh and raster.
  double close_mm = 0.0;
  /// When > 0 (--crease-width-mm), a hinge is a crease when the fold angle summed across a band
  /// of this width (millimetres of the flat sheet) exceeds the threshold
  /// (creases/crease_band.hpp); the crease map is then closed over the same width unless
  /// close_mm is given.
  double crease_width_mm = 0.0;
  int crease_px = 1;                              ///< crease line width in pixels
  int bootstrap = 200;                            ///< resamples for the a interval and KS p-value
  /// The resolution floor of the truncated facet law (fits/truncated_shape.hpp), in mean mesh
  /// triangles (--facet-floor-triangles): facets smaller than this are left out of that fit.
  double facet_floor_triangles = 4.0;
  std::uint64_t seed = 1;                         ///< seed of the resampling
  /// The analysing program's version and git revision, written into stats.json beside the
  /// run's own (the app sets them; the library does not know its build).
  std::string program_version, git_revision;
};

struct FacetRecord {
  int id = 0;
  double area_m2 = 0, x = 0, xi = 0;  ///< physical area, fraction of the sheet, x / mean x
  bool touches_border = false;
};

/// Shape statistics of one cycle's facets (docs/STATISTICS.md §3.3-3.4, §3.7).
struct ShapeStats {
  double a_fit = 0, a_fit_lo = 0, a_fit_hi = 0;  ///< MLE and its bootstrap 95 % interval
  double a_moment = 0;                           ///< NaN when the variance vanishes
  double a_univ = 0;                             ///< root of (a+1)/a^3 = tau^2 s
  double ks = 0, ks_p = 0;                       ///< KS distance to phi(.; a_fit), bootstrap p
  double ks_univ = 0;                            ///< KS distance to phi(.; a_univ)
};

/// The same law fitted to the facets at or above the resolution floor only, with its scale free
/// (fits/truncated_shape.hpp): the comparison with the experiments that the mesh allows.
struct FloorShapeStats {
  double floor_x = 0;        ///< the floor, as a fraction of the sheet
  long n_facets = 0;         ///< facets at or above it
  double a_fit = 0;          ///< shape of the fitted law
  double mean_x = 0;         ///< that law's mean area s (fraction of the sheet)
  double a_univ = 0;         ///< the universal curve at s
  double law_share_below = 0;  ///< the law's share of facets under the floor
  double ks = 0, ks_p = 0;   ///< KS distance to the truncated law, parametric-bootstrap p
  /// On an edge of the search (fits/truncated_shape.hpp FitEdge): a_fit, mean_x, a_univ and
  /// law_share_below are then not estimates, and the KS test is of the edge's law.
  FitEdge edge = FitEdge::none;
};

struct CycleResult {
  int cycle = 0;
  std::optional<double> compaction;  ///< as the run file recorded it for the cycle (CycleData)
  long crease_edges = 0, new_crease_edges = 0;
  double crease_length_m = 0, crease_length_L0 = 0;
  double new_crease_length_m = 0, new_crease_length_L0 = 0;
  double perimeter_P = 0;  ///< docs/STATISTICS.md §2.1, in L0
  /// 1 - P / (l/L0): the share of the plastic-edge length that separates no two facets (crease
  /// segments ending inside a facet); nullopt when l = 0. Slightly negative values are pixel
  /// error of P on a network without dangling ends.
  std::optional<double> dangling_fraction;
  /// Plastic rotation over L0 (radians): creases/crease_edges.hpp plastic_rotation, over every
  /// hinge; and the share of it the creased hinges carry (nullopt when it is zero). A mesh that
  /// spreads a fold over more hinge rows keeps the first and lowers the second.
  double plastic_rotation_L0 = 0;
  std::optional<double> creased_rotation_share;
  /// crease_length_L0 over RunAnalysis::hinge_length_L0: how full the mesh's hinge network is.
  /// Where it nears the share at which most facets are single triangles, crease growth is
  /// bounded by the mesh, not the sheet.
  double creased_hinge_share = 0;
  std::vector<StageCreases> stages;  ///< per stage end of the cycle, lengths in L0
  std::optional<double> new_length_share_after_compress;  ///< see share_after_last()
  std::vector<FacetRecord> facets;
  /// Facets smaller than 1.5 mean mesh triangles, i.e. not larger than one triangle: at the
  /// mesh's resolution floor (docs/STATISTICS.md §3.7, resolution floor).
  long n_single_triangle_facets = 0;
  std::optional<double> single_triangle_fraction;  ///< of n_facets; nullopt without facets
  double mean_x = 0, mean_area_m2 = 0;
  long sheet_px = 0, crease_px = 0, speck_px = 0;
  std::optional<ShapeStats> shape;  ///< absent with fewer than 2 facets
  /// Absent with fewer than 5 facets above the floor (or no finite likelihood for them).
  std::optional<FloorShapeStats> shape_above_floor;
  std::vector<DensityBin> distribution;
  cv::Mat crease_image, facet_image;
};

struct RunAnalysis {
  double L0_m = 0, area_m2 = 0, px_per_m = 0;
  /// The closing kernel as applied, in pixels (from --close-mm when given; odd, 0 = none).
  int close_px = 0;
  int image_width = 0, image_height = 0;
  double mean_triangle_area_m2 = 0;  ///< the mesh floor: creases cannot enclose less
  /// The rest length of every hinge's edge over L0: the most crease length the mesh can hold.
  double hinge_length_L0 = 0;
  double pixel_floor_m2 = 0;         ///< min_facet_px pixels
  double smallest_resolvable_m2 = 0; ///< the larger of the two floors
  double facet_floor_m2 = 0;         ///< floor of the truncated facet law (AnalyzeOptions)
  /// The compaction ratio D every cycle recorded, for c1, c2 (run/compaction.hpp); unset, with
  /// compaction_note saying why, when the cycles do not all give one and the same value.
  std::optional<double> compaction;
  std::string compaction_note;
  std::vector<CycleResult> cycles;
  ThresholdRule threshold_rule;  ///< the threshold used and how it was derived
  ThresholdSensitivity sensitivity;
  std::optional<LogLawFit> fit_length, fit_P;  ///< cumulative l/L0 and P against n
  /// The same law fitted to the per-cycle increments of l/L0 and of P (fits/log_law.hpp says
  /// why this fit's uncertainties are the ones to quote).
  std::optional<LogLawFit> fit_length_increments, fit_P_increments;
  std::string fit_note;  ///< why a fit is missing, if it is
  std::vector<std::string> warnings;
};

/// Throws InputError (io/run_reader.hpp) when no threshold can be derived (c0 = 0 without
/// --threshold).
/// `opt` with px_per_cm resolved for this run's mesh when px_per_edge asks for it, and the
/// closing kernel in pixels when close_mm asks for it.
AnalyzeOptions raster_for_mesh(const RunData& run, const AnalyzeOptions& opt);

RunAnalysis analyze_run(const RunData& run, const AnalyzeOptions& opt);

}  // namespace crumple::analysis
