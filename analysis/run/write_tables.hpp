// The per-stage crease accounting and the threshold sensitivity table as stats.json pieces and
// as CSV tables (stages.csv, sensitivity.csv); run/write_results.cpp puts them in place.
#pragma once

#include "analysis/run/analyze_run.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <ostream>

namespace crumple::analysis {

/// A value or JSON null.
nlohmann::json json_or_null(const std::optional<double>& v);

/// cycles[i]["stages"]: [{"index", "stage", "t", "crease_edges", "crease_length_L0",
/// "new_crease_length_L0", "lost_crease_length_L0"}, ...].
nlohmann::json stages_json(const CycleResult& c);

/// stats.json "threshold_sensitivity": {"factors_of_c0", "thresholds", "cycles": [{"cycle",
/// "crease_length_L0", "perimeter_P", "n_facets"}]}.
nlohmann::json sensitivity_json(const ThresholdSensitivity& s);

/// stats.json "parameters.threshold_rule".
nlohmann::json threshold_rule_json(const ThresholdRule& r);

/// stages.csv: cycle,stage_index,stage,t,crease_edges,crease_length_L0,new_crease_length_L0
void write_stages_csv(std::ostream& out, const RunAnalysis& res);

/// sensitivity.csv: cycle,factor_of_c0,threshold,crease_length_L0,perimeter_P,n_facets
void write_sensitivity_csv(std::ostream& out, const ThresholdSensitivity& s);

}  // namespace crumple::analysis
