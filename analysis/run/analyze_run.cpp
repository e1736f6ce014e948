// Per-run analysis; see analyze_run.hpp.
#include "analysis/run/analyze_run.hpp"

#include "analysis/fits/facet_shape.hpp"
#include "analysis/fits/shape_bootstrap.hpp"
#include "analysis/fits/truncated_shape.hpp"
#include "analysis/io/run_reader.hpp"
#include "analysis/raster/crease_map.hpp"
#include "analysis/raster/raster_frame.hpp"
#include "analysis/run/compaction.hpp"
#include "analysis/run/config_params.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>

namespace crumple::analysis {
namespace {

ShapeStats shape_stats(const std::vector<double>& x, const AnalyzeOptions& opt,
                       std::uint64_t seed) {
  ShapeStats s;
  const auto xi = scaled_areas(x);
  s.a_fit = fit_a_mle(xi);
  const Interval iv = bootstrap_a_interval(x, opt.bootstrap, seed);
  s.a_fit_lo = iv.lo;
  s.a_fit_hi = iv.hi;
  try {
    s.a_moment = a_moment(xi);
  } catch (const std::invalid_argument&) {
    s.a_moment = std::numeric_limits<double>::quiet_NaN();  // all facets equal
  }
  double mean = 0;
  for (double v : x) mean += v;
  s.a_univ = a_universal(mean / static_cast<double>(x.size()));
  s.ks = ks_distance(xi, s.a_fit);
  s.ks_p = ks_pvalue_parametric(xi.size(), s.a_fit, s.ks, opt.bootstrap, seed + 7919);
  s.ks_univ = ks_distance(xi, s.a_univ);
  return s;
}

/// The truncated law over the facets at or above floor_x (fractions of the sheet); nullopt with
/// fewer than 5 there, or when no law in the searched range gives them a finite likelihood.
std::optional<FloorShapeStats> floor_shape_stats(const std::vector<double>& x, double floor_x,
                                                 const AnalyzeOptions& opt, std::uint64_t seed) {
  const auto above = std::count_if(x.begin(), x.end(), [&](double v) { return v >= floor_x; });
  if (above < 5) return std::nullopt;
  TruncatedShapeFit fit;
  try {
    fit = fit_truncated_shape(x, floor_x);
  } catch (const std::runtime_error&) {
    return std::nullopt;
  }
  FloorShapeStats s;
  s.floor_x = floor_x;
  s.n_facets = static_cast<long>(fit.n);
  s.a_fit = fit.a;
  s.mean_x = fit.mean_x;
  s.a_univ = a_universal(fit.mean_x);
  s.law_share_below = fit.share_below;
  s.edge = fit.edge;
  s.ks = truncated_ks_distance(x, fit);
  s.ks_p = truncated_ks_pvalue(fit, s.ks, opt.bootstrap, seed);
  return s;
}

/// The threshold rule of the options for this run's c0 (from /config, else the default).
ThresholdRule resolve_threshold(const RunData& run, const AnalyzeOptions& opt,
                                std::vector<std::string>& warnings) {
  const std::optional<double> c0_cfg = plastic_c0_from_config(run.config_yaml);
  const double c0 = c0_cfg.value_or(kDefaultPlasticC0);
  if (!c0_cfg) {
    std::ostringstream w;
    w << "/config gives no integrator.plastic_c0; assuming the simulator default c0 = "
      << kDefaultPlasticC0 << " for the crease threshold";
    warnings.push_back(w.str());
  }
  try {
    if (opt.threshold) return absolute_threshold(*opt.threshold, c0, c0_cfg.has_value());
    if (opt.crease_angle)
      return threshold_from_crease_angle(*opt.crease_angle, c0, c0_cfg.has_value(), false);
    // The run's own crease angle is the default; an explicit --threshold-c0 overrides it.
    if (const auto angle = crease_angle_from_config(run.config_yaml); angle && !opt.threshold_c0_given)
      return threshold_from_crease_angle(*angle, c0, c0_cfg.has_value(), true);
    return threshold_from_c0(opt.threshold_c0, c0, c0_cfg.has_value());
  } catch (const std::invalid_argument& e) {
    throw InputError(run.path + ": " + e.what());
  }
}

/// Stage ends grouped by cycle, in run order; warns about stage ends of unfinished cycles.
std::map<int, std::vector<const StageEndData*>> stages_by_cycle(
    const RunData& run, std::vector<std::string>& warnings) {
  std::map<int, std::vector<const StageEndData*>> out;
  std::set<int> completed;
  for (const auto& c : run.cycles) completed.insert(c.cycle);
  std::set<int> orphans;
  for (const auto& s : run.stage_ends) {
    if (completed.count(s.cycle))
      out[s.cycle].push_back(&s);
    else
      orphans.insert(s.cycle);
  }
  for (int c : orphans)
    warnings.push_back("/stage_ends has stages of cycle " + std::to_string(c) +
                       ", which did not complete; they are not reported");
  if (run.has_stage_ends)
    for (int c : completed)
      if (!out.count(c))
        warnings.push_back("/stage_ends has no stage of cycle " + std::to_string(c));
  return out;
}

/// Per-stage accounting of one cycle into r, lengths in L0.
void add_stages(CycleResult& r, const MeshData& mesh, double L0,
                const std::vector<const StageEndData*>& stages, const std::vector<char>& now,
                const std::vector<char>& before, double threshold, const CreaseBand* band,
                std::vector<std::string>& warnings) {
  r.stages = account_stages(mesh, stages, now, before, threshold, band);
  double sum = 0.0;
  for (auto& s : r.stages) {
    s.crease_length /= L0;
    s.new_length /= L0;
    s.lost_length /= L0;
    sum += s.new_length;
  }
  r.new_length_share_after_compress =
      share_after_last(r.stages, "compress", r.new_crease_length_L0);
  if (!r.stages.empty() && std::abs(sum - r.new_crease_length_L0) > 1e-9 * (1 + sum))
    warnings.push_back("cycle " + std::to_string(r.cycle) + ": the stages' new crease lengths add "
                       "up to " + std::to_string(sum) + " L0, not the cycle's " +
                       std::to_string(r.new_crease_length_L0) +
                       " L0 (the last stage end is not the cycle end)");
}

/// Both fits of the log law to y against the cycle numbers n (cumulative and increments).
void fit_law(const std::vector<double>& n, const std::vector<double>& y,
             std::optional<LogLawFit>& cumulative, std::optional<LogLawFit>& increments) {
  if (std::none_of(y.begin(), y.end(), [](double v) { return v > 0; })) return;
  cumulative = fit_log_law(n, y);
  // y_0 = 0: before the first cycle the sheet is flat and has no creases.
  std::vector<double> from, to, dy;
  for (std::size_t i = 0; i < n.size(); ++i) {
    from.push_back(i == 0 ? 0.0 : n[i - 1]);
    to.push_back(n[i]);
    dy.push_back(y[i] - (i == 0 ? 0.0 : y[i - 1]));
  }
  if (std::any_of(dy.begin(), dy.end(), [](double v) { return v > 0; }))
    increments = fit_log_law_increments(from, to, dy);
}

/// The largest crease map, in pixels across: 1e4 x 1e4 8-bit maps and their 32-bit facet labels
/// take about 0.5 GB. A sheet that would need more is a wrong length unit or resolution, and
/// OpenCV would fail on it deep inside (or the int extents overflow).
constexpr double kMaxRasterSidePx = 1e4;

/// Refuses a mesh whose raster cannot be made: no extent, or too many pixels across.
void check_raster_size(const RunData& run, const AnalyzeOptions& opt) {
  const double size = sheet_size(run.mesh), area = sheet_area(run.mesh);
  if (!(size > 0) || !(area > 0))
    throw InputError(run.path + ": /mesh/ref_positions: the sheet has no area (size " +
                     std::to_string(size) + ", area " + std::to_string(area) + ")");
  const double side_px = size * opt.px_per_cm * 100.0 * run.length_unit_m;
  if (!(side_px <= kMaxRasterSidePx)) {
    std::ostringstream m;
    m << run.path << ": the crease map would be " << side_px << " pixels across (more than "
      << kMaxRasterSidePx << "): the sheet is " << size * run.length_unit_m
      << " m wide (/mesh/ref_positions times /meta@length_unit_m = " << run.length_unit_m
      << ") at --px-per-cm " << opt.px_per_cm;
    throw InputError(m.str());
  }
}

}  // namespace

AnalyzeOptions raster_for_mesh(const RunData& run, const AnalyzeOptions& opt) {
  AnalyzeOptions o = opt;
  if (opt.px_per_edge > 0) {
    // The mean edge of an equilateral triangle of the mean area, as the warning below measures.
    const double edge_m =
        std::sqrt(4.0 * mean_triangle_area(run.mesh) / std::sqrt(3.0)) * run.length_unit_m;
    o.px_per_cm = opt.px_per_edge / (100.0 * edge_m);
  }
  // A band of creases is drawn row by row; closed over its width it is one crease.
  if (opt.close_mm <= 0 && opt.crease_width_mm > 0) o.close_mm = opt.crease_width_mm;
  if (o.close_mm > 0)
    o.segment.close_px = static_cast<int>(std::lround(o.close_mm * 0.1 * o.px_per_cm));
  return o;
}

RunAnalysis analyze_run(const RunData& run, const AnalyzeOptions& opt_given) {
  const AnalyzeOptions opt = raster_for_mesh(run, opt_given);
  RunAnalysis out;
  const MeshData& mesh = run.mesh;
  check_raster_size(run, opt);
  const double unit = run.length_unit_m;
  out.L0_m = sheet_size(mesh) * unit;
  out.area_m2 = sheet_area(mesh) * unit * unit;
  out.hinge_length_L0 =
      crease_length(mesh, std::vector<char>(mesh.hinges.size(), 1)) * unit / out.L0_m;
  const RunCompaction compaction = run_compaction(run.cycles);
  out.compaction = compaction.value;
  out.compaction_note = compaction.note;
  out.warnings = run.warnings;
  out.threshold_rule = resolve_threshold(run, opt, out.warnings);
  const double threshold = out.threshold_rule.threshold;

  const double px_per_unit = opt.px_per_cm * 100.0 * unit;
  MeasureContext ctx;
  ctx.mesh = &mesh;
  ctx.frame = make_frame(mesh, px_per_unit);
  ctx.sheet = sheet_mask(mesh, ctx.frame);
  ctx.L0 = sheet_size(mesh);
  ctx.L0_px = ctx.L0 * px_per_unit;
  ctx.segment = opt.segment;
  ctx.crease_px = opt.crease_px;
  std::optional<CreaseBand> band;
  if (opt.crease_width_mm > 0) {
    band.emplace(mesh, opt.crease_width_mm * 1e-3 / unit);
    ctx.band = &*band;
  }
  out.px_per_m = opt.px_per_cm * 100.0;
  out.close_px = closing_kernel_px(opt.segment.close_px);
  out.image_width = ctx.frame.width;
  out.image_height = ctx.frame.height;
  out.mean_triangle_area_m2 = mean_triangle_area(mesh) * unit * unit;
  out.pixel_floor_m2 = opt.segment.min_facet_px / (out.px_per_m * out.px_per_m);
  out.smallest_resolvable_m2 = std::max(out.mean_triangle_area_m2, out.pixel_floor_m2);
  out.facet_floor_m2 = std::max(opt.facet_floor_triangles * out.mean_triangle_area_m2,
                                out.pixel_floor_m2);
  // A triangle's side should span several pixels, or a one-triangle facet vanishes under the
  // crease lines and the closing and the raster, not the mesh, sets the floor.
  const double edge_px = std::sqrt(4.0 * out.mean_triangle_area_m2 / std::sqrt(3.0)) * out.px_per_m;
  // A closing asked for in millimetres is meant to merge what lies closer than that, so only
  // the raster's own closing counts here.
  const int raster_close_px = opt.close_mm > 0 ? 0 : opt.segment.close_px;
  if (edge_px < 4.0 * opt.crease_px + raster_close_px)
    out.warnings.push_back("mean mesh edge is only " + std::to_string(edge_px) +
                           " px: raise --px-per-cm so the smallest facets are resolved");

  const auto stage_ends = stages_by_cycle(run, out.warnings);
  std::vector<char> previous;
  for (const CycleData& c : run.cycles) {
    CycleResult r;
    r.cycle = c.cycle;
    r.compaction = c.compaction;
    CreaseMeasure m = measure_creases(ctx, c.p, threshold);
    const auto fresh = new_creases(m.creased, previous);
    r.crease_edges = m.crease_edges;
    for (char f : fresh) r.new_crease_edges += f;
    r.crease_length_m = m.length * unit;
    r.new_crease_length_m = crease_length(mesh, fresh) * unit;
    r.crease_length_L0 = r.crease_length_m / out.L0_m;
    r.new_crease_length_L0 = r.new_crease_length_m / out.L0_m;
    if (out.hinge_length_L0 > 0) r.creased_hinge_share = r.crease_length_L0 / out.hinge_length_L0;
    const double rotation = plastic_rotation(mesh, c.p);
    r.plastic_rotation_L0 = rotation * unit / out.L0_m;
    if (rotation > 0) r.creased_rotation_share = plastic_rotation(mesh, c.p, &m.creased) / rotation;
    const auto st = stage_ends.find(c.cycle);
    if (st != stage_ends.end())
      add_stages(r, mesh, ctx.L0, st->second, m.creased, previous, threshold, ctx.band,
                 out.warnings);
    previous = m.creased;

    const Segmentation& seg = m.seg;
    r.sheet_px = seg.sheet_px;
    r.crease_px = seg.crease_px;
    r.speck_px = seg.speck_px;
    r.perimeter_P = m.perimeter_P;
    if (r.crease_length_L0 > 0) r.dangling_fraction = 1.0 - r.perimeter_P / r.crease_length_L0;
    // Areas as fractions of the sheet's pixels, then in m^2 through the exact triangle area,
    // so the rasterisation of the outline does not bias the physical areas.
    std::vector<double> x;
    for (const Facet& f : seg.facets) {
      FacetRecord fr;
      fr.id = f.label;
      fr.x = static_cast<double>(f.px) / static_cast<double>(seg.sheet_px);
      fr.area_m2 = fr.x * out.area_m2;
      fr.touches_border = f.touches_border;
      x.push_back(fr.x);
      r.n_single_triangle_facets += fr.area_m2 < 1.5 * out.mean_triangle_area_m2;
      r.facets.push_back(fr);
    }
    if (!x.empty()) {
      r.single_triangle_fraction =
          static_cast<double>(r.n_single_triangle_facets) / static_cast<double>(x.size());
      const auto xi = scaled_areas(x);
      for (std::size_t i = 0; i < xi.size(); ++i) r.facets[i].xi = xi[i];
      r.mean_x = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
      r.mean_area_m2 = r.mean_x * out.area_m2;
      r.distribution = log_binned_density(xi);
    }
    if (x.size() >= 2) r.shape = shape_stats(x, opt, opt.seed + static_cast<std::uint64_t>(c.cycle));
    r.shape_above_floor = floor_shape_stats(x, out.facet_floor_m2 / out.area_m2, opt,
                                            opt.seed + 104729 + static_cast<std::uint64_t>(c.cycle));
    r.crease_image = crease_map_image(mesh, c.p, m.creased, ctx.frame, std::max(opt.crease_px, 1));
    r.facet_image = facet_image(seg);
    out.cycles.push_back(std::move(r));
  }
  out.sensitivity = threshold_sensitivity(ctx, run.cycles, out.threshold_rule.c0);

  std::vector<double> n, l, P;
  for (const auto& r : out.cycles) {
    n.push_back(r.cycle);
    l.push_back(r.crease_length_L0);
    P.push_back(r.perimeter_P);
  }
  if (n.size() < 3) {
    out.fit_note = "log-law fit needs at least 3 cycles, the run has " + std::to_string(n.size());
  } else {
    fit_law(n, l, out.fit_length, out.fit_length_increments);
    fit_law(n, P, out.fit_P, out.fit_P_increments);
    if (!out.fit_length) out.fit_note = "no creases above the threshold in any cycle";
  }
  return out;
}

}  // namespace crumple::analysis
