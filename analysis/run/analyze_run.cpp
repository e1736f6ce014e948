// Per-run analysis; see analyze_run.hpp.
#include "analysis/run/analyze_run.hpp"

#include "analysis/fits/facet_shape.hpp"
#include "analysis/fits/shape_bootstrap.hpp"
#include "analysis/raster/crease_map.hpp"
#include "analysis/raster/raster_frame.hpp"
#include "analysis/run/config_params.hpp"

#include <cmath>
#include <limits>
#include <numeric>

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

}  // namespace

RunAnalysis analyze_run(const RunData& run, const AnalyzeOptions& opt) {
  RunAnalysis out;
  const MeshData& mesh = run.mesh;
  const double unit = run.length_unit_m;
  out.L0_m = sheet_size(mesh) * unit;
  out.area_m2 = sheet_area(mesh) * unit * unit;
  out.compaction = compaction_from_config(run.config_yaml);
  out.warnings = run.warnings;

  const double px_per_unit = opt.px_per_cm * 100.0 * unit;
  const RasterFrame frame = make_frame(mesh, px_per_unit);
  out.px_per_m = opt.px_per_cm * 100.0;
  out.image_width = frame.width;
  out.image_height = frame.height;
  out.mean_triangle_area_m2 = mean_triangle_area(mesh) * unit * unit;
  out.pixel_floor_m2 = opt.segment.min_facet_px / (out.px_per_m * out.px_per_m);
  out.smallest_resolvable_m2 = std::max(out.mean_triangle_area_m2, out.pixel_floor_m2);
  // A triangle's side should span several pixels, or a one-triangle facet vanishes under the
  // crease lines and the closing and the raster, not the mesh, sets the floor.
  const double edge_px = std::sqrt(4.0 * out.mean_triangle_area_m2 / std::sqrt(3.0)) * out.px_per_m;
  if (edge_px < 4.0 * opt.crease_px + opt.segment.close_px)
    out.warnings.push_back("mean mesh edge is only " + std::to_string(edge_px) +
                           " px: raise --px-per-cm so the smallest facets are resolved");

  const cv::Mat sheet = sheet_mask(mesh, frame);
  const double L0_px = sheet_size(mesh) * px_per_unit;
  std::vector<char> previous;
  for (const CycleData& c : run.cycles) {
    CycleResult r;
    r.cycle = c.cycle;
    const auto creased = crease_hinges(c.p, opt.threshold);
    const auto fresh = new_creases(creased, previous);
    previous = creased;
    for (char f : creased) r.crease_edges += f;
    for (char f : fresh) r.new_crease_edges += f;
    r.crease_length_m = crease_length(mesh, creased) * unit;
    r.new_crease_length_m = crease_length(mesh, fresh) * unit;
    r.crease_length_L0 = r.crease_length_m / out.L0_m;
    r.new_crease_length_L0 = r.new_crease_length_m / out.L0_m;

    const Segmentation seg =
        segment_facets(sheet, crease_layer(mesh, creased, frame, opt.crease_px), opt.segment);
    r.sheet_px = seg.sheet_px;
    r.crease_px = seg.crease_px;
    r.speck_px = seg.speck_px;
    r.perimeter_P = perimeter_crease_length(seg, L0_px);
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
      r.facets.push_back(fr);
    }
    if (!x.empty()) {
      const auto xi = scaled_areas(x);
      for (std::size_t i = 0; i < xi.size(); ++i) r.facets[i].xi = xi[i];
      r.mean_x = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
      r.mean_area_m2 = r.mean_x * out.area_m2;
      r.distribution = log_binned_density(xi);
    }
    if (x.size() >= 2) r.shape = shape_stats(x, opt, opt.seed + static_cast<std::uint64_t>(c.cycle));
    r.crease_image = crease_map_image(mesh, c.p, creased, frame, std::max(opt.crease_px, 1));
    r.facet_image = facet_image(seg);
    out.cycles.push_back(std::move(r));
  }

  std::vector<double> n, l, P;
  for (const auto& r : out.cycles) {
    n.push_back(r.cycle);
    l.push_back(r.crease_length_L0);
    P.push_back(r.perimeter_P);
  }
  auto positive = [](const std::vector<double>& v) {
    for (double e : v)
      if (e > 0) return true;
    return false;
  };
  if (n.size() < 3)
    out.fit_note = "log-law fit needs at least 3 cycles, the run has " + std::to_string(n.size());
  else {
    if (positive(l)) out.fit_length = fit_log_law(n, l);
    if (positive(P)) out.fit_P = fit_log_law(n, P);
    if (!out.fit_length) out.fit_note = "no creases above the threshold in any cycle";
  }
  return out;
}

}  // namespace crumple::analysis
