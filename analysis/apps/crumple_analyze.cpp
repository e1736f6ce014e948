// crumple-analyze: crease length, crease maps, facets and fits of one run file, and the
// ensemble statistics and fits over several analysed runs (analysis/README.md).
//
//   crumple-analyze RUN.h5 [-o DIR] [--threshold-c0 F | --threshold P] [--px-per-cm R] ...
//   crumple-analyze ensemble -o ENSEMBLE.json DIR... (DIR: a run's output folder or its stats.json)
//   crumple-analyze collapse -o COLLAPSE.json ENSEMBLE.json... (one ensemble per compaction ratio)
//
// Exit codes: 0 success, 2 bad input (arguments, run file, stats.json or output folder; nothing
// is written), 1 anything else (an earlier output is then left as it was).
#include "analysis/ensemble/collapse.hpp"
#include "analysis/ensemble/ensemble.hpp"
#include "analysis/io/run_reader.hpp"
#include "analysis/run/analyze_run.hpp"
#include "analysis/run/write_results.hpp"

#include "crumple/version.hpp"

#include <CLI/CLI.hpp>

#include <cstdlib>

#include <filesystem>
#include <iostream>

namespace {

/// `crumple-analyze ensemble`: reads every stats.json, writes ensemble.json, prints the fits.
int run_ensemble(const std::vector<std::string>& inputs, const std::string& out_path) {
  using namespace crumple::analysis;
  std::vector<RunStats> runs;
  for (const auto& p : inputs) runs.push_back(read_run_stats(p));
  const EnsembleJson doc = ensemble_json(runs);
  write_ensemble(out_path, doc);
  std::cout << "crumple-analyze ensemble: " << runs.size() << " runs, " << doc["cycles"].size()
            << " cycles -> " << out_path << "\n";
  for (const auto& note : doc["notes"]) std::cout << "  note: " << note.get<std::string>() << "\n";
  for (const char* q : {"perimeter_P", "crease_length_L0"}) {
    const auto& f = doc["fits"][q]["increments"];
    if (f.contains("error")) {
      std::cout << "  log law on the increments of " << q << ": " << f["error"].get<std::string>()
                << "\n";
      continue;
    }
    std::cout << "  log law on the increments of " << q << ": C = " << f["C"] << " +- "
              << f["sigma_C"] << ", n0 = " << f["n0"] << " +- " << f["sigma_n0"]
              << ", chi2/dof = " << f["chi2"] << "/" << f["dof"] << "\n";
  }
  return 0;
}

/// `crumple-analyze collapse`: reads the ensembles, writes collapse.json, prints the global fits.
int run_collapse(const std::vector<std::string>& inputs, const std::string& out_path) {
  using namespace crumple::analysis;
  std::vector<EnsembleInput> ensembles;
  for (const auto& p : inputs) ensembles.push_back(read_ensemble(p));
  const EnsembleJson doc = collapse_json(ensembles);
  write_ensemble(out_path, doc);
  std::cout << "crumple-analyze collapse: " << ensembles.size() << " ensembles, compaction "
            << doc["compactions"].dump() << " -> " << out_path << "\n";
  for (const auto& note : doc["notes"]) std::cout << "  note: " << note.get<std::string>() << "\n";
  for (const char* q : {"perimeter_P", "crease_length_L0"}) {
    const auto& f = doc["fits"][q]["increments"];
    std::cout << "  global law on the increments of " << q << ": ";
    if (f.contains("error"))
      std::cout << f["error"].get<std::string>() << "\n";
    else
      std::cout << "c1 = " << f["c1"] << " +- " << f["sigma_c1"] << ", c2 = " << f["c2"]
                << " +- " << f["sigma_c2"] << ", chi2/dof = " << f["chi2"] << "/" << f["dof"]
                << "\n";
  }
  return 0;
}

}  // namespace

namespace {

using namespace crumple::analysis;

/// The per-run analysis options (thresholds, raster, segmentation, resampling).
void add_run_options(CLI::App& app, AnalyzeOptions& opt, double& absolute, double& angle) {
  CLI::Option* by_c0 =
      app.add_option("--threshold-c0", opt.threshold_c0,
                     "crease when |p| > F c0, c0 the run's yield curvature (integrator.plastic_c0 "
                     "in /config): the hinge keeps a permanent set of at least F times the "
                     "largest bend the sheet takes back elastically; the default unless the run's "
                     "/config states output.crease_angle (then |p| > 2 sin(angle/2))")
          ->capture_default_str()
          ->check(CLI::PositiveNumber);
  CLI::Option* by_value =
      app.add_option("--threshold", absolute,
                     "crease when |p| > P, an absolute threshold (p in curvature units "
                     "2 sin(theta/2)) instead of --threshold-c0")
          ->check(CLI::PositiveNumber)
          ->excludes(by_c0);
  app.add_option("--crease-angle", angle,
                 "crease when the permanent fold exceeds this many degrees, |p| > 2 sin(angle/2), "
                 "as a protocol's output.crease_angle states it (for runs made without it)")
      ->check(CLI::Number)
      ->check([](const std::string& s) {
        // CLI::Number has vetted s; a fold of 0 or 180 degrees is no crease angle.
        const double a = std::strtod(s.c_str(), nullptr);
        return a > 0 && a < 180 ? std::string() : "must lie strictly between 0 and 180 degrees";
      })
      ->excludes(by_c0)
      ->excludes(by_value);
  auto* px_cm = app.add_option("--px-per-cm", opt.px_per_cm, "raster resolution of the crease map")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--px-per-edge", opt.px_per_edge,
                 "raster resolution from the mesh instead: the mean mesh edge spans this many "
                 "pixels (for comparing resolutions; P grows with the raster until about 20)")
      ->check(CLI::PositiveNumber)
      ->excludes(px_cm);
  app.add_option("--min-facet-px", opt.segment.min_facet_px,
                 "regions below this many pixels are specks, not facets")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  auto* close_px = app.add_option("--close-px", opt.segment.close_px,
                                  "closing kernel (pixels) that bridges small gaps in creases; <= 1 "
                                  "disables")
      ->capture_default_str();
  app.add_option("--close-mm", opt.close_mm,
                 "closing kernel in millimetres of the flat sheet instead: crease lines closer "
                 "than this merge and the facets between them vanish, at one physical scale on "
                 "every mesh (docs/studies/convergence_flat_unfold_closed/)")
      ->check(CLI::PositiveNumber)
      ->excludes(close_px);
  app.add_option("--crease-width-mm", opt.crease_width_mm,
                 "count a hinge as a crease when the fold angle summed over the hinges beside it, "
                 "within a band this many millimetres wide, exceeds the threshold, so that a fold "
                 "a fine mesh spreads over parallel rows counts once (analysis/creases/"
                 "crease_band.hpp); the crease map is closed over the same width unless "
                 "--close-mm says otherwise")
      ->check(CLI::PositiveNumber)
      ->excludes(close_px);
  app.add_option("--watershed-h-px", opt.segment.watershed_h_px,
                 "also cut facets at their necks, as the experiments' segmentation does: a marker "
                 "watershed of the distance to the nearest crease, seeded at the domes higher "
                 "than this many pixels (the experiments used 4); 0 = no cuts, a gap in a crease "
                 "merges the facets on its two sides")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--crease-px", opt.crease_px, "crease line width in pixels (1 or 2)")
      ->capture_default_str()
      ->check(CLI::Range(1, 3));
  app.add_option("--bootstrap", opt.bootstrap,
                 "resamples for the a_fit interval and the KS p-value")
      ->capture_default_str()
      ->check(CLI::Range(10, 100000));
  app.add_option("--facet-floor-triangles", opt.facet_floor_triangles,
                 "resolution floor, in mean mesh triangles, of the facet law fitted to the facets "
                 "above it (the *_above_floor keys)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--seed", opt.seed, "seed of the resampling")->capture_default_str();
}

/// Runs `work` and turns its exceptions into the exit codes: 2 bad input, 1 anything else.
template <class Work>
int guarded(const char* who, Work work) {
  try {
    return work();
  } catch (const InputError& e) {
    std::cerr << who << ": bad input: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << who << ": error: " << e.what() << "\n";
    return 1;
  }
}

/// `crumple-analyze ensemble` and `collapse`: the per-run options mean nothing there, so they
/// are refused rather than ignored.
template <class Work>
int subcommand_main(const CLI::App& app, const std::string& name, Work work) {
  for (const CLI::Option* o : app.get_options())
    if (o->count() > 0) {
      std::cerr << "crumple-analyze " << name << ": " << o->get_name()
                << " is an option of the per-run analysis, not of the " << name << "\n";
      return 2;
    }
  return guarded(("crumple-analyze " + name).c_str(), work);
}

/// Per cycle: crease length, P, facets and a_fit; then the log-law fits.
void print_summary(const std::string& run_path, const std::string& out_dir,
                   const RunAnalysis& res) {
  std::cout << "crumple-analyze: " << res.cycles.size() << " cycles of " << run_path
            << " analysed into " << out_dir << "\n  " << res.threshold_rule.note << "\n";
  for (const auto& c : res.cycles)
    std::cout << "  cycle " << c.cycle << ": crease length " << c.crease_length_m << " m ("
              << c.crease_length_L0 << " L0), P " << c.perimeter_P << ", facets "
              << c.facets.size() << (c.shape ? ", a_fit " + std::to_string(c.shape->a_fit) : "")
              << "\n";
  if (res.fit_length)
    std::cout << "  log law on l/L0: C = " << res.fit_length->C << " +- "
              << res.fit_length->sigma_C << ", n0 = " << res.fit_length->n0 << " +- "
              << res.fit_length->sigma_n0 << " (cumulative)\n";
  if (res.fit_length_increments)
    std::cout << "  log law on the increments of l/L0: C = " << res.fit_length_increments->C
              << " +- " << res.fit_length_increments->sigma_C
              << ", n0 = " << res.fit_length_increments->n0 << " +- "
              << res.fit_length_increments->sigma_n0 << "\n";
}

/// One run: read (validated), check the output folder, analyse, write it whole.
int analyze_main(const std::string& run_path, std::string out_dir, const AnalyzeOptions& opt) {
  return guarded("crumple-analyze", [&] {
    const RunData run = read_run(run_path);
    if (out_dir.empty())
      out_dir = std::filesystem::path(run_path).replace_extension(".analysis").string();
    check_output_dir(out_dir);
    const RunAnalysis res = analyze_run(run, opt);
    for (const auto& w : res.warnings) std::cerr << "crumple-analyze: warning: " << w << "\n";
    write_results(out_dir, run, res, opt);
    print_summary(run_path, out_dir, res);
    return 0;
  });
}

}  // namespace

int main(int argc, char** argv) {
  AnalyzeOptions opt;
  opt.program_version = crumple::kVersion;
  opt.git_revision = crumple::kGitRevision;
  std::string run_path, out_dir;
  CLI::App app{"crumple-analyze: crease length, crease maps, facet segmentation and fits of a "
               "crumple run file (writes stats.json, CSVs and PNGs); `crumple-analyze ensemble "
               "--help` for the statistics over several runs"};
  app.set_version_flag("--version",
                       std::string("crumple-analyze ") + crumple::kVersion + " (git " + crumple::kGitRevision + ")");
  app.footer(
      "Files written (into RUN.analysis/ or -o DIR; analysis/README.md):\n"
      "  stats.json          per cycle crease length, P, facets, fits, the threshold and its rule\n"
      "  cycles.csv          the per-cycle table; stages.csv: crease length at every stage end\n"
      "  sensitivity.csv     crease length, P and facet count against the crease threshold\n"
      "  facets.csv, distribution.csv   facet areas and their distribution per cycle\n"
      "  crease_NNNN.png, facets_NNNN.png   crease map and segmented facets per cycle\n"
      "Exit codes: 0 done; 2 bad input (arguments, run file or output folder: nothing is\n"
      "written); 1 any other error (an earlier output folder is left as it was).");
  // Not required by CLI11: the ensemble subcommand has no run file (checked after parsing).
  app.add_option("run", run_path, "run file (RUN.h5) written by crumple-sim");
  std::vector<std::string> ens_inputs;
  std::string ens_out;
  CLI::App* ens = app.add_subcommand(
      "ensemble",
      "ensemble statistics over several runs of one protocol: per cycle the mean, seed-to-seed "
      "s.d. and s.e.m. of every per-cycle quantity, the per-stage and threshold-sensitivity "
      "tables, and the log-law fits to the ensemble means weighted by their s.e.m. "
      "(docs/STATISTICS.md §2.3); written as JSON");
  ens->add_option("analyses", ens_inputs,
                  "the runs' crumple-analyze output folders (or their stats.json files)")
      ->required();
  ens->add_option("-o,--output", ens_out, "ensemble JSON file to write (e.g. results/ensemble.json)")
      ->required();
  ens->footer("Exit codes: 0 done; 2 bad input (a missing or unreadable stats.json: nothing is "
              "written); 1 any other error.");
  std::vector<std::string> col_inputs;
  std::string col_out;
  CLI::App* col = app.add_subcommand(
      "collapse",
      "the crease-length law l = c1 (1 - D) ln(1 + c2 n/D) fitted to several compaction ratios "
      "at once (the collapse, docs/STATISTICS.md §2.3), from one ensemble document per ratio, "
      "with each ratio's own fit and the collapsed points; written as JSON");
  col->add_option("ensembles", col_inputs,
                  "ensemble documents (`crumple-analyze ensemble` output), one per compaction")
      ->required();
  col->add_option("-o,--output", col_out, "collapse JSON file to write")->required();
  col->footer("Exit codes: 0 done; 2 bad input (a missing or unreadable ensemble document, or one "
              "without a single compaction ratio: nothing is written); 1 any other error.");
  app.add_option("-o,--output", out_dir,
                 "output folder (default: the run file's name with .h5 replaced by .analysis)");
  double absolute = 0.0, angle = 0.0;
  add_run_options(app, opt, absolute, angle);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  if (ens->parsed())
    return subcommand_main(app, "ensemble", [&] { return run_ensemble(ens_inputs, ens_out); });
  if (col->parsed())
    return subcommand_main(app, "collapse", [&] { return run_collapse(col_inputs, col_out); });
  if (run_path.empty()) {
    std::cerr << app.help() << "crumple-analyze: the run file (RUN.h5) is required\n";
    return 2;
  }
  if (app.count("--threshold")) opt.threshold = absolute;
  if (app.count("--threshold-c0")) opt.threshold_c0_given = true;
  if (app.count("--crease-angle")) opt.crease_angle = angle;
  return analyze_main(run_path, out_dir, opt);
}
