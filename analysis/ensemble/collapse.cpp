// The global fit over compaction ratios; see collapse.hpp.
#include "analysis/ensemble/collapse.hpp"

#include "analysis/ensemble/ensemble_tables.hpp"
#include "analysis/fits/log_law.hpp"
#include "analysis/io/run_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>

namespace crumple::analysis {

using namespace ensemble_detail;

namespace {

// The fitted measures, as in the ensemble: P first, the experiments' measure.
const char* const kQuantities[] = {"perimeter_P", "crease_length_L0"};

/// The series of one measure over every ratio: increments (primary) or cumulative means.
struct Series {
  std::vector<double> D, from, to, y, sigma;
  bool all_sigma = true;
};

Series gather(const std::vector<EnsembleInput>& inputs, const std::string& key, bool increments) {
  Series s;
  for (const auto& in : inputs) {
    const double D = in.doc.at("compaction").get<double>();
    std::vector<double> sems;  // this ratio's
    for (const auto& row : in.doc.at("cycles")) {
      const auto m = number(row, key + "_mean");
      if (!m) continue;
      const int n = row.at("cycle").get<int>();
      const auto e = number(row, key + "_sem");
      s.D.push_back(D);
      s.from.push_back(increments ? n - 1.0 : 0.0);
      s.to.push_back(n);
      s.y.push_back(*m);
      s.all_sigma = s.all_sigma && e && *e > 0;
      sems.push_back(e.value_or(0.0));
    }
    // Each ratio's s.e.m. moderated within its own series, as its ensemble's fit does (their
    // spreads differ by ratio: smaller compaction ratios give larger increments).
    const std::vector<double> mod = moderated_sems(sems);
    s.sigma.insert(s.sigma.end(), mod.begin(), mod.end());
  }
  return s;
}

EnsembleJson fit_json(const Series& s, bool increments) {
  const std::string model =
      increments ? "increments: dl_n = c1 (1 - D) [ln(1 + c2 n/D) - ln(1 + c2 (n-1)/D)]"
                 : "cumulative: l_n = c1 (1 - D) ln(1 + c2 n/D) (values correlated between "
                   "cycles)";
  CollapseFit f;
  try {
    f = fit_collapse(s.D, s.from, s.to, s.y, s.all_sigma ? s.sigma : std::vector<double>{});
  } catch (const std::invalid_argument& e) {
    return {{"model", model}, {"error", e.what()}};
  }
  const auto finite = [](double v) { return or_null(std::isfinite(v) ? std::optional(v) : std::nullopt); };
  return {{"model", model},
          {"method", "least squares over every (D, cycle) point at once, c1 solved exactly for "
                     "each c2 and chi2 minimised over ln c2 within 1e-6 <= c2 <= 1e6 "
                     "(analysis/fits/log_law.cpp fit_collapse); covariance " +
                         std::string(s.all_sigma ? "(J^T W J)^-1 with the absolute sigmas"
                                                 : "s^2 (J^T J)^-1, scaled by the residuals")},
          {"c1", finite(f.c1)},
          {"sigma_c1", finite(f.sigma_c1)},
          {"c2", finite(f.c2)},
          {"sigma_c2", finite(f.sigma_c2)},
          {"corr_c1_c2", finite(f.corr)},
          {"chi2", finite(f.chi2)},
          {"dof", f.dof},
          {"points", f.points},
          {"weighted", s.all_sigma},
          {"converged", f.converged},
          {"at_bound", f.at_bound},
          {"weights_note", s.all_sigma ? "weighted by the seed-to-seed s.e.m., each ratio's "
                                         "variances averaged half and half with their mean "
                                         "(moderated)"
                                       : "unweighted (some point has no seed-to-seed s.e.m.: "
                                         "fewer than 2 runs or a zero spread); errors scaled by "
                                         "the residuals"}};
}

/// Per ratio: its runs, and its own increment fit's c1, c2 (from its ensemble document).
EnsembleJson group_json(const EnsembleInput& in) {
  EnsembleJson g = {{"compaction", in.doc.at("compaction")},
                    {"source", in.path},
                    {"n_runs", in.doc.value("n_runs", 0)},
                    {"seeds", in.doc.value("seeds", EnsembleJson::array())},
                    {"cycles", in.doc.at("cycles").size()}};
  EnsembleJson fits = EnsembleJson::object();
  for (const char* q : kQuantities) {
    const EnsembleJson f = in.doc.contains("fits") && in.doc["fits"].contains(q)
                               ? in.doc["fits"][q].value("increments", EnsembleJson::object())
                               : EnsembleJson::object();
    EnsembleJson out = EnsembleJson::object();
    for (const char* k : {"c1", "sigma_c1", "c2", "sigma_c2", "C", "n0", "chi2", "dof", "error"})
      if (f.contains(k)) out[k] = f[k];
    fits[q] = std::move(out);
  }
  g["fits"] = std::move(fits);
  return g;
}

/// The points of the collapse figure: x = n/D against y = mean/(1 - D) with the s.e.m. scaled
/// alike.
EnsembleJson points_json(const std::vector<EnsembleInput>& inputs, const std::string& key) {
  EnsembleJson pts = EnsembleJson::array();
  for (const auto& in : inputs) {
    const double D = in.doc.at("compaction").get<double>();
    for (const auto& row : in.doc.at("cycles")) {
      const auto m = number(row, key + "_mean");
      if (!m) continue;
      const int n = row.at("cycle").get<int>();
      const auto e = number(row, key + "_sem");
      pts.push_back({{"compaction", D},
                     {"cycle", n},
                     {"mean", *m},
                     {"sem", or_null(e)},
                     {"x", n / D},
                     {"y", *m / (1 - D)},
                     {"y_sem", or_null(e ? std::optional(*e / (1 - D)) : std::nullopt)}});
    }
  }
  return pts;
}

}  // namespace

EnsembleInput read_ensemble(const std::string& path) {
  std::ifstream f(path);
  if (!std::filesystem::is_regular_file(path) || !f)
    throw InputError(path + ": no such file (give `crumple-analyze ensemble` documents)");
  EnsembleInput in;
  in.path = path;
  try {
    in.doc = EnsembleJson::parse(f);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path + ": not valid JSON (" + e.what() + ")");
  }
  if (!in.doc.is_object() || !in.doc.contains("cycles") || !in.doc["cycles"].is_array() ||
      in.doc["cycles"].empty())
    throw InputError(path + ": no cycles (not an ensemble document?)");
  const auto D = number(in.doc, "compaction");
  if (!D)
    throw InputError(path + ": no single compaction ratio (" +
                     (in.doc.contains("compaction_note") && in.doc["compaction_note"].is_string()
                          ? in.doc["compaction_note"].get<std::string>()
                          : std::string("\"compaction\" is null")) +
                     "); the collapse needs one D per ensemble");
  if (!(*D > 0 && *D < 1)) throw InputError(path + ": compaction must lie in (0, 1)");
  return in;
}

EnsembleJson collapse_json(const std::vector<EnsembleInput>& inputs) {
  if (inputs.empty()) throw std::invalid_argument("collapse_json: no ensembles");
  EnsembleJson notes = EnsembleJson::array();
  std::set<double> ratios;
  for (const auto& in : inputs) ratios.insert(in.doc.at("compaction").get<double>());
  if (ratios.size() < inputs.size())
    notes.push_back("some compaction ratios appear in more than one ensemble; their points "
                    "enter the fit side by side");
  if (ratios.size() < 2)
    notes.push_back("one compaction ratio only: the global fit is that ratio's own fit, and "
                    "nothing is collapsed");
  EnsembleJson groups = EnsembleJson::array();
  for (const auto& in : inputs) groups.push_back(group_json(in));
  EnsembleJson fits = EnsembleJson::object(), points = EnsembleJson::object();
  for (const char* q : kQuantities) {
    fits[q] = {{"increments", fit_json(gather(inputs, std::string(q) + "_increment", true), true)},
               {"cumulative", fit_json(gather(inputs, q, false), false)}};
    points[q] = points_json(inputs, q);
  }
  fits["note"] = "increments: primary (errors from the seed-to-seed s.e.m. of each cycle's "
                 "increment, close to independent between cycles). cumulative: the same law "
                 "on the cumulative means, whose errors are correlated between cycles.";
  EnsembleJson out;
  out["law"] = "l = c1 (1 - D) ln(1 + c2 n / D) (docs/STATISTICS.md §2.3)";
  out["compactions"] = EnsembleJson(std::vector<double>(ratios.begin(), ratios.end()));
  out["notes"] = std::move(notes);
  out["groups"] = std::move(groups);
  out["fits"] = std::move(fits);
  out["points"] = std::move(points);
  return out;
}

}  // namespace crumple::analysis
