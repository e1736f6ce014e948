// Per-stage and sensitivity outputs; see write_tables.hpp.
#include "analysis/run/write_tables.hpp"

#include <cmath>

namespace crumple::analysis {

nlohmann::json json_or_null(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? nlohmann::json(*v) : nlohmann::json();
}

nlohmann::json stages_json(const CycleResult& c) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& s : c.stages)
    out.push_back({{"index", s.index},
                   {"stage", s.stage},
                   {"t", s.t},
                   {"crease_edges", s.crease_edges},
                   {"crease_length_L0", s.crease_length},
                   {"new_crease_length_L0", s.new_length},
                   {"lost_crease_length_L0", s.lost_length}});
  return out;
}

nlohmann::json sensitivity_json(const ThresholdSensitivity& s) {
  nlohmann::json cycles = nlohmann::json::array();
  for (const auto& c : s.cycles)
    cycles.push_back({{"cycle", c.cycle},
                      {"crease_length_L0", c.crease_length_L0},
                      {"perimeter_P", c.perimeter_P},
                      {"n_facets", c.n_facets}});
  return {{"factors_of_c0", s.factors}, {"thresholds", s.thresholds}, {"cycles", cycles}};
}

nlohmann::json threshold_rule_json(const ThresholdRule& r) {
  if (r.kind == ThresholdRule::Kind::Absolute) return {{"kind", "absolute"}};
  if (r.kind == ThresholdRule::Kind::CreaseAngle)
    return {{"kind", "crease_angle"},
            {"angle_deg", r.angle_deg},
            {"angle_source", r.angle_from_config ? "config" : "option"}};
  return {{"kind", "fraction_of_c0"},
          {"factor", r.factor},
          {"c0", r.c0},
          {"c0_source", r.c0_from_config ? "config" : "default"}};
}

void write_stages_csv(std::ostream& out, const RunAnalysis& res) {
  out << "cycle,stage_index,stage,t,crease_edges,crease_length_L0,new_crease_length_L0\n";
  for (const auto& c : res.cycles)
    for (const auto& s : c.stages)
      out << c.cycle << ',' << s.index << ',' << s.stage << ',' << s.t << ',' << s.crease_edges
          << ',' << s.crease_length << ',' << s.new_length << '\n';
}

void write_sensitivity_csv(std::ostream& out, const ThresholdSensitivity& s) {
  out << "cycle,factor_of_c0,threshold,crease_length_L0,perimeter_P,n_facets\n";
  for (const auto& c : s.cycles)
    for (std::size_t k = 0; k < s.factors.size(); ++k)
      out << c.cycle << ',' << s.factors[k] << ',' << s.thresholds[k] << ','
          << c.crease_length_L0[k] << ',' << c.perimeter_P[k] << ',' << c.n_facets[k] << '\n';
}

}  // namespace crumple::analysis
