// Writes a RunAnalysis into an output folder: stats.json, cycles.csv, stages.csv,
// sensitivity.csv, facets.csv, distribution.csv, crease_NNNN.png and facets_NNNN.png (the
// outputs of crumple-analyze).
#pragma once

#include "analysis/io/run_data.hpp"
#include "analysis/run/analyze_run.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace crumple::analysis {

/// The stats.json document (also used by tests without touching the disk).
nlohmann::json stats_json(const RunData& run, const RunAnalysis& res, const AnalyzeOptions& opt);

/// Throws InputError (before any analysing) when `dir` cannot become the output folder: it
/// exists and is not a folder, a parent is not a folder, or the nearest existing parent is not
/// writable.
void check_output_dir(const std::string& dir);

/// Writes every output file into a hidden sibling folder of `dir`, then puts it in place of
/// `dir` (replacing an earlier analysis whole), so `dir` is never left half written; throws
/// std::runtime_error on I/O errors, with the sibling removed.
void write_results(const std::string& dir, const RunData& run, const RunAnalysis& res,
                   const AnalyzeOptions& opt);

}  // namespace crumple::analysis
