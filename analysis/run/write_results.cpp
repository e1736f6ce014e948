// Output files of crumple-analyze; see write_results.hpp.
#include "analysis/run/write_results.hpp"

#include "analysis/facets/area_distribution.hpp"
#include "analysis/fits/facet_shape.hpp"
#include "analysis/io/run_reader.hpp"
#include "analysis/run/write_tables.hpp"

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

namespace crumple::analysis {
namespace {

/// NaN and infinities are not JSON; they become null.
nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

nlohmann::json fit_json(const std::optional<LogLawFit>& f, const std::optional<double>& D) {
  if (!f) return nullptr;
  nlohmann::json j = {{"model", f->model},
                      {"C", num(f->C)},
                      {"sigma_C", num(f->sigma_C)},
                      {"n0", num(f->n0)},
                      {"sigma_n0", num(f->sigma_n0)},
                      {"corr_C_n0", num(f->corr)},
                      {"rss", num(f->rss)},
                      {"dof", f->dof},
                      {"reduced_chi2", num(f->chi2_red)},
                      {"r2", num(f->r2)},
                      {"converged", f->converged},
                      {"at_bound", f->at_bound},
                      {"iterations", f->iterations}};
  if (D) {
    const auto k = to_experiment_constants(*f, *D);
    j["c1"] = num(k.c1);
    j["sigma_c1"] = num(k.sigma_c1);
    j["c2"] = num(k.c2);
    j["sigma_c2"] = num(k.sigma_c2);
    j["n0_experiment"] = 10.0 * *D;  // n0 = D / c2 with c2 = 0.1 (docs/STATISTICS.md §2.2)
  }
  return j;
}

std::string cycle_tag(int cycle) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%04d", cycle);
  return buf;
}

/// An optional CSV value: empty where stats.json has null.
struct Cell {
  const std::optional<double>& v;
};
std::ostream& operator<<(std::ostream& o, const Cell& c) {
  if (c.v && std::isfinite(*c.v)) o << *c.v;
  return o;
}

std::ofstream open_out(const std::filesystem::path& p) {
  std::ofstream f(p);
  if (!f) throw std::runtime_error("cannot write " + p.string());
  f.precision(10);
  return f;
}

}  // namespace

nlohmann::json stats_json(const RunData& run, const RunAnalysis& res, const AnalyzeOptions& opt) {
  nlohmann::json j;
  j["input"] = {{"path", run.path},
                {"meta", run.meta},
                {"length_unit_m", run.length_unit_m},
                {"compaction", json_or_null(res.compaction)},
                {"compaction_note",
                 res.compaction_note.empty() ? nlohmann::json() : nlohmann::json(res.compaction_note)},
                {"n_cycles", run.cycles.size()}};
  j["analysis"] = {{"program", "crumple-analyze"},
                   {"program_version", opt.program_version},
                   {"git_revision", opt.git_revision}};
  j["warnings"] = res.warnings;
  j["parameters"] = {
      {"threshold", res.threshold_rule.threshold},
      {"threshold_rule", threshold_rule_json(res.threshold_rule)},
      {"threshold_note", res.threshold_rule.note},
      {"px_per_cm", res.px_per_m / 100.0},
      {"px_per_edge", opt.px_per_edge > 0 ? nlohmann::json(opt.px_per_edge) : nlohmann::json()},
      {"crease_px", opt.crease_px},
      {"close_px", res.close_px},
      {"close_mm", opt.close_mm > 0 ? nlohmann::json(opt.close_mm) : nlohmann::json()},
      {"crease_width_mm",
       opt.crease_width_mm > 0 ? nlohmann::json(opt.crease_width_mm) : nlohmann::json()},
      {"min_facet_px", opt.segment.min_facet_px},
      {"watershed_h_px", opt.segment.watershed_h_px},
      {"bootstrap_resamples", opt.bootstrap},
      {"facet_floor_triangles", opt.facet_floor_triangles},
      {"seed", opt.seed},
      {"area_bin_ratio", kAreaBinRatio},
      {"tau", kTau}};
  j["sheet"] = {{"L0_m", res.L0_m},
                {"area_m2", res.area_m2},
                {"nodes", run.mesh.ref_positions.size()},
                {"triangles", run.mesh.triangles.size()},
                {"hinges", run.mesh.hinges.size()},
                {"hinge_length_L0", res.hinge_length_L0},
                {"image_width_px", res.image_width},
                {"image_height_px", res.image_height},
                {"px_per_m", res.px_per_m}};
  j["resolution"] = {{"mean_triangle_area_m2", res.mean_triangle_area_m2},
                     {"pixel_floor_m2", res.pixel_floor_m2},
                     {"smallest_resolvable_area_m2", res.smallest_resolvable_m2},
                     {"smallest_resolvable_x", res.smallest_resolvable_m2 / res.area_m2},
                     {"facet_floor_m2", res.facet_floor_m2},
                     {"facet_floor_x", res.facet_floor_m2 / res.area_m2}};
  j["cycles"] = nlohmann::json::array();
  for (const auto& c : res.cycles) {
    nlohmann::json cj = {{"cycle", c.cycle},
                         {"compaction", json_or_null(c.compaction)},
                         {"crease_edges", c.crease_edges},
                         {"new_crease_edges", c.new_crease_edges},
                         {"crease_length_m", c.crease_length_m},
                         {"crease_length_L0", c.crease_length_L0},
                         {"new_crease_length_m", c.new_crease_length_m},
                         {"new_crease_length_L0", c.new_crease_length_L0},
                         {"perimeter_P", c.perimeter_P},
                         {"dangling_fraction", json_or_null(c.dangling_fraction)},
                         {"plastic_rotation_L0", c.plastic_rotation_L0},
                         {"creased_rotation_share", json_or_null(c.creased_rotation_share)},
                         {"creased_hinge_share", c.creased_hinge_share},
                         {"stages", stages_json(c)},
                         {"new_length_share_after_compress",
                          json_or_null(c.new_length_share_after_compress)},
                         {"n_facets", c.facets.size()},
                         {"n_single_triangle_facets", c.n_single_triangle_facets},
                         {"single_triangle_fraction", json_or_null(c.single_triangle_fraction)},
                         {"n_border_facets", std::count_if(c.facets.begin(), c.facets.end(),
                                                           [](auto& f) { return f.touches_border; })},
                         {"mean_area_x", c.mean_x},
                         {"mean_area_m2", c.mean_area_m2},
                         {"mean_area_L0sq", c.mean_area_m2 / (res.L0_m * res.L0_m)},
                         {"sheet_px", c.sheet_px},
                         {"crease_px", c.crease_px},
                         {"speck_px", c.speck_px},
                         {"smallest_resolvable_xi",
                          c.mean_x > 0 ? num(res.smallest_resolvable_m2 / res.area_m2 / c.mean_x)
                                       : nlohmann::json()}};
    if (c.shape) {
      const auto& s = *c.shape;
      cj["a_fit"] = num(s.a_fit);
      cj["a_fit_interval95"] = {num(s.a_fit_lo), num(s.a_fit_hi)};
      cj["a_moment"] = num(s.a_moment);
      cj["a_univ"] = num(s.a_univ);
      cj["ks_distance"] = num(s.ks);
      cj["ks_pvalue"] = num(s.ks_p);
      cj["ks_distance_univ"] = num(s.ks_univ);
    }
    // Flat keys, so that the ensemble averages them as the others (ensemble/ensemble.cpp).
    if (c.shape_above_floor) {
      const auto& f = *c.shape_above_floor;
      cj["floor_x"] = num(f.floor_x);
      cj["n_facets_above_floor"] = f.n_facets;
      // On an edge of the search the law is not estimated (fits/truncated_shape.hpp FitEdge):
      // no shape, mean or share; the KS test is of the edge's law, and the edge is named.
      const bool on_edge = f.edge != FitEdge::none;
      const auto est = [&](double v) { return on_edge ? nlohmann::json() : num(v); };
      cj["a_fit_above_floor"] = est(f.a_fit);
      cj["mean_area_x_above_floor"] = est(f.mean_x);
      cj["a_univ_above_floor"] = est(f.a_univ);
      cj["law_share_below_floor"] = est(f.law_share_below);
      cj["ks_distance_above_floor"] = num(f.ks);
      cj["ks_pvalue_above_floor"] = num(f.ks_p);
      cj["fit_above_floor_edge"] = on_edge ? nlohmann::json(fit_edge_name(f.edge)) : nlohmann::json();
    }
    j["cycles"].push_back(cj);
  }
  j["threshold_sensitivity"] = sensitivity_json(res.sensitivity);
  j["log_fit"] = {
      {"crease_length_L0", fit_json(res.fit_length, res.compaction)},
      {"perimeter_P", fit_json(res.fit_P, res.compaction)},
      {"crease_length_L0_increments", fit_json(res.fit_length_increments, res.compaction)},
      {"perimeter_P_increments", fit_json(res.fit_P_increments, res.compaction)},
      {"note", res.fit_note},
      // Why c1, c2 are missing from the fits, when they are (run/compaction.hpp).
      {"compaction_note",
       res.compaction_note.empty() ? nlohmann::json() : nlohmann::json(res.compaction_note)}};
  return j;
}

namespace {

/// `dir` without a trailing separator ("out/" names the folder "out").
std::filesystem::path folder_path(const std::string& dir) {
  std::filesystem::path p = std::filesystem::path(dir).lexically_normal();
  if (p.filename().empty() && p.has_parent_path()) p = p.parent_path();
  return p;
}

void write_files(const std::filesystem::path& dir, const RunData& run, const RunAnalysis& res,
                 const AnalyzeOptions& opt) {
  auto stats = open_out(dir / "stats.json");
  stats << stats_json(run, res, opt).dump(2) << "\n";

  auto cyc = open_out(dir / "cycles.csv");
  cyc << "cycle,crease_edges,crease_length_m,crease_length_L0,new_crease_length_m,perimeter_P,"
         "n_facets,mean_area_m2,mean_area_x,a_fit,a_fit_lo,a_fit_hi,a_moment,a_univ,ks_distance,"
         "ks_pvalue,new_crease_length_L0,dangling_fraction,n_single_triangle_facets,"
         "single_triangle_fraction,new_length_share_after_compress,compaction,"
         "n_facets_above_floor,a_fit_above_floor,mean_area_x_above_floor,a_univ_above_floor,"
         "law_share_below_floor,ks_distance_above_floor,ks_pvalue_above_floor,"
         "fit_above_floor_edge\n";
  auto fac = open_out(dir / "facets.csv");
  fac << "cycle,facet_id,area_m2,x,xi,touches_border\n";
  auto dis = open_out(dir / "distribution.csv");
  dis << "cycle,bin_lo,bin_hi,count,density\n";
  for (const auto& c : res.cycles) {
    cyc << c.cycle << ',' << c.crease_edges << ',' << c.crease_length_m << ','
        << c.crease_length_L0 << ',' << c.new_crease_length_m << ',' << c.perimeter_P << ','
        << c.facets.size() << ',' << c.mean_area_m2 << ',' << c.mean_x;
    if (c.shape)
      cyc << ',' << c.shape->a_fit << ',' << c.shape->a_fit_lo << ',' << c.shape->a_fit_hi << ','
          << c.shape->a_moment << ',' << c.shape->a_univ << ',' << c.shape->ks << ','
          << c.shape->ks_p;
    else
      cyc << ",,,,,,,";
    cyc << ',' << c.new_crease_length_L0 << ',' << Cell{c.dangling_fraction} << ','
        << c.n_single_triangle_facets << ',' << Cell{c.single_triangle_fraction} << ','
        << Cell{c.new_length_share_after_compress} << ',' << Cell{c.compaction};
    if (c.shape_above_floor) {
      const auto& f = *c.shape_above_floor;
      cyc << ',' << f.n_facets;
      if (f.edge != FitEdge::none)
        cyc << ",,,,";
      else
        cyc << ',' << f.a_fit << ',' << f.mean_x << ',' << f.a_univ << ',' << f.law_share_below;
      cyc << ',' << f.ks << ',' << f.ks_p << ',' << fit_edge_name(f.edge) << '\n';
    } else {
      cyc << ",,,,,,,,\n";
    }
    for (const auto& f : c.facets)
      fac << c.cycle << ',' << f.id << ',' << f.area_m2 << ',' << f.x << ',' << f.xi << ','
          << (f.touches_border ? 1 : 0) << '\n';
    for (const auto& b : c.distribution)
      dis << c.cycle << ',' << b.lo << ',' << b.hi << ',' << b.count << ',' << b.density << '\n';
    const std::string tag = cycle_tag(c.cycle);
    if (!cv::imwrite((dir / ("crease_" + tag + ".png")).string(), c.crease_image) ||
        !cv::imwrite((dir / ("facets_" + tag + ".png")).string(), c.facet_image))
      throw std::runtime_error("cannot write PNGs into " + dir.string());
  }
  auto stg = open_out(dir / "stages.csv");
  write_stages_csv(stg, res);
  auto sen = open_out(dir / "sensitivity.csv");
  write_sensitivity_csv(sen, res.sensitivity);
  // close() flushes; a full disk shows here, not in the buffered writes above.
  for (std::ofstream* f : {&stats, &cyc, &fac, &dis, &stg, &sen}) f->close();
  if (!stats || !cyc || !fac || !dis || !stg || !sen)
    throw std::runtime_error("error writing the output files into " + dir.string());
}

}  // namespace

void check_output_dir(const std::string& dir_s) {
  namespace fs = std::filesystem;
  const fs::path dir = folder_path(dir_s);
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError(dir_s + ": the output folder exists and is not a folder");
  fs::path p = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
  while (!fs::exists(p, ec) && p.has_parent_path() && p != p.parent_path()) p = p.parent_path();
  if (!fs::is_directory(p, ec))
    throw InputError(dir_s + ": cannot make the output folder: " + p.string() +
                     " is not a folder");
  if (::access(p.c_str(), W_OK | X_OK) != 0)
    throw InputError(dir_s + ": cannot make the output folder: " + p.string() +
                     " is not writable");
}

void write_results(const std::string& dir_s, const RunData& run, const RunAnalysis& res,
                   const AnalyzeOptions& opt) {
  namespace fs = std::filesystem;
  const fs::path dir = folder_path(dir_s);
  const fs::path parent = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
  fs::create_directories(parent);
  // Built by appending, not as "." + string: GCC 12 warns of a false overlap (-Wrestrict) there.
  std::string tag(1, '.');
  tag += dir.filename().string();
  tag += '.';
  tag += std::to_string(::getpid());
  const fs::path tmp = parent / (tag + ".tmp"), old = parent / (tag + ".old");
  fs::remove_all(tmp);
  try {
    fs::create_directory(tmp);
    write_files(tmp, run, res, opt);
    if (fs::exists(dir)) {
      fs::rename(dir, old);
      fs::rename(tmp, dir);
      fs::remove_all(old);
    } else {
      fs::rename(tmp, dir);
    }
  } catch (...) {
    std::error_code ec;
    fs::remove_all(tmp, ec);
    if (!fs::exists(dir, ec) && fs::exists(old, ec)) fs::rename(old, dir, ec);  // put it back
    throw;
  }
}

}  // namespace crumple::analysis
