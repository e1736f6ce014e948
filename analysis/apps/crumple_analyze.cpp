// crumple-analyze: crease length, crease maps, facets and fits of one run file
// (analysis/README.md).
//
//   crumple-analyze RUN.h5 [-o DIR] [--threshold-c0 F | --threshold P] [--px-per-cm R] ...
//
// Exit codes: 0 success, 2 bad input (arguments, run file or output folder; nothing is
// written), 1 anything else (an earlier output folder is then left as it was).
#include "analysis/io/run_reader.hpp"
#include "analysis/run/analyze_run.hpp"
#include "analysis/run/write_results.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
  using namespace crumple::analysis;
  AnalyzeOptions opt;
  std::string run_path, out_dir;
  CLI::App app{"crumple-analyze: crease length, crease maps, facet segmentation and fits of a "
               "crumple run file (writes stats.json, CSVs and PNGs)"};
  app.footer("Exit codes: 0 done; 2 bad input (arguments, run file or output folder: nothing is "
             "written); 1 any other error (an earlier output folder is left as it was).");
  app.add_option("run", run_path, "run file (RUN.h5) written by crumple-sim")->required();
  app.add_option("-o,--output", out_dir,
                 "output folder (default: the run file's name with .h5 replaced by .analysis)");
  double absolute = 0.0;
  CLI::Option* by_c0 =
      app.add_option("--threshold-c0", opt.threshold_c0,
                     "crease when |p| > F c0, c0 the run's yield curvature (integrator.plastic_c0 "
                     "in /config): the hinge keeps a permanent set of at least F times the "
                     "largest bend the sheet takes back elastically")
          ->capture_default_str()
          ->check(CLI::PositiveNumber);
  app.add_option("--threshold", absolute,
                 "crease when |p| > P, an absolute threshold (p in curvature units "
                 "2 sin(theta/2)) instead of --threshold-c0")
      ->check(CLI::PositiveNumber)
      ->excludes(by_c0);
  app.add_option("--px-per-cm", opt.px_per_cm, "raster resolution of the crease map")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--min-facet-px", opt.segment.min_facet_px,
                 "regions below this many pixels are specks, not facets")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--close-px", opt.segment.close_px,
                 "closing kernel (pixels) that bridges small gaps in creases; <= 1 disables")
      ->capture_default_str();
  app.add_option("--crease-px", opt.crease_px, "crease line width in pixels (1 or 2)")
      ->capture_default_str()
      ->check(CLI::Range(1, 3));
  app.add_option("--bootstrap", opt.bootstrap,
                 "resamples for the a_fit interval and the KS p-value")
      ->capture_default_str()
      ->check(CLI::Range(10, 100000));
  app.add_option("--seed", opt.seed, "seed of the resampling")->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  try {
    if (app.count("--threshold")) opt.threshold = absolute;
    const RunData run = read_run(run_path);
    if (out_dir.empty())
      out_dir = std::filesystem::path(run_path).replace_extension(".analysis").string();
    check_output_dir(out_dir);
    const RunAnalysis res = analyze_run(run, opt);
    for (const auto& w : res.warnings) std::cerr << "crumple-analyze: warning: " << w << "\n";
    write_results(out_dir, run, res, opt);
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
    return 0;
  } catch (const InputError& e) {
    std::cerr << "crumple-analyze: bad input: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "crumple-analyze: error: " << e.what() << "\n";
    return 1;
  }
}
