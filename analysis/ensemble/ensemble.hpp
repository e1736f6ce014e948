// The ensemble over several runs of one protocol (`crumple-analyze ensemble`): from each run's
// stats.json (the per-run output of crumple-analyze) it computes, per cycle, the mean, the
// seed-to-seed standard deviation and the standard error of the mean of every per-cycle
// quantity and of the per-cycle increments of l/L0 and P, the tallies of the KS tests, the
// per-stage and threshold-sensitivity tables, the compaction ratio the runs agree on, and the
// log-law fits to the ensemble means weighted by their standard errors (docs/STATISTICS.md §2.3).
//
// This is the only implementation of the ensemble statistics and of the ensemble fits: the
// pipeline's scripts (pipeline/plots/, pipeline/report/) read the document it writes and only
// plot and tabulate it. analysis/README.md lists the document's keys.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace crumple::analysis {

/// Ordered, so ensemble.json and the tables made from it keep the order the keys were written in.
using EnsembleJson = nlohmann::ordered_json;

/// One run's stats.json and where it came from.
struct RunStats {
  std::string path;  ///< the stats.json file
  EnsembleJson stats;
};

/// Mean, standard deviation (n - 1 in the denominator) and standard error of the mean
/// (s.d. / sqrt(n)) of the finite values among `values`; missing values and NaN are left out.
/// mean needs one value, s.d. and s.e.m. two.
struct SampleStats {
  std::optional<double> mean, sd, sem;
  int n = 0;
};
SampleStats sample_stats(const std::vector<std::optional<double>>& values);

/// Reads `path`/stats.json, or `path` itself when it is a file. Throws InputError (naming the
/// file) when it is missing, not JSON, or has no cycles.
RunStats read_run_stats(const std::string& path);

/// What the fit is fitted to: the per-cycle increments dy_n = y_n - y_(n-1) (y_0 = 0), or the
/// cumulative values y_n.
enum class LawSeries { Increments, Cumulative };

/// The log law y = C ln(1 + n/n0) fitted (fits/log_law.hpp) to one series of ensemble means at
/// the cycles `n`: weighted by `sigma` (absolute 1-sigma errors, the seed-to-seed s.e.m.) when
/// given, otherwise unweighted with the covariance scaled by the residuals. With 0 < D < 1 it
/// adds c1 = C/(1 - D) and c2 = D/n0 with their errors. A fit that cannot be made (fewer than 3
/// cycles, no crease length) is {"model", "error"}.
EnsembleJson ensemble_fit(LawSeries series, const std::vector<int>& n, const std::vector<double>& y,
                          const std::optional<std::vector<double>>& sigma,
                          const std::optional<double>& D);

/// The ensemble document (ensemble.json) of `runs` (at least one).
EnsembleJson ensemble_json(const std::vector<RunStats>& runs);

/// Writes `doc` to `path` (its folder made if missing) through a temporary file renamed into
/// place, so `path` is never left half written; throws std::runtime_error on failure.
void write_ensemble(const std::string& path, const EnsembleJson& doc);

}  // namespace crumple::analysis
