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

/// Creates `dir` if needed and writes every output file; throws std::runtime_error on I/O errors.
void write_results(const std::string& dir, const RunData& run, const RunAnalysis& res,
                   const AnalyzeOptions& opt);

}  // namespace crumple::analysis
