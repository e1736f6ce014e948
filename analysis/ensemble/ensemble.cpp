// Ensemble statistics and fits over runs; see ensemble.hpp.
#include "analysis/ensemble/ensemble.hpp"

#include "analysis/ensemble/ensemble_tables.hpp"
#include "analysis/fits/log_law.hpp"
#include "analysis/io/run_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace crumple::analysis {

using namespace ensemble_detail;

SampleStats sample_stats(const std::vector<std::optional<double>>& values) {
  std::vector<double> v;
  for (const auto& x : values)
    if (x && std::isfinite(*x)) v.push_back(*x);
  SampleStats s;
  s.n = static_cast<int>(v.size());
  if (v.empty()) return s;
  double sum = 0;
  for (double x : v) sum += x;
  const double mean = sum / static_cast<double>(v.size());
  s.mean = mean;
  if (v.size() < 2) return s;
  double ss = 0;
  for (double x : v) ss += (x - mean) * (x - mean);
  s.sd = std::sqrt(ss / static_cast<double>(v.size() - 1));
  s.sem = *s.sd / std::sqrt(static_cast<double>(v.size()));
  return s;
}

RunStats read_run_stats(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path file = fs::is_directory(path, ec) ? fs::path(path) / "stats.json" : fs::path(path);
  if (!fs::is_regular_file(file, ec))
    throw InputError(file.string() + ": no such file (give crumple-analyze's output folders or "
                                     "their stats.json)");
  std::ifstream in(file);
  RunStats r;
  r.path = file.string();
  try {
    r.stats = EnsembleJson::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(r.path + ": not valid JSON (" + e.what() + ")");
  }
  const auto it = r.stats.find("cycles");
  if (!r.stats.is_object() || it == r.stats.end() || !it->is_array() || it->empty())
    throw InputError(r.path + " has no cycles");
  for (const auto& c : *it)
    if (!c.is_object() || !c.contains("cycle") || !c["cycle"].is_number_integer())
      throw InputError(r.path + ": a cycle without an integer \"cycle\"");
  return r;
}

namespace {

// The quantities averaged per cycle (stats.json "cycles" keys).
const char* const kKeys[] = {"crease_length_L0", "crease_length_m", "new_crease_length_L0",
                             "perimeter_P", "dangling_fraction", "plastic_rotation_L0",
                             "creased_rotation_share", "creased_hinge_share", "n_facets",
                             "n_single_triangle_facets", "single_triangle_fraction",
                             "new_length_share_after_compress", "a_fit", "a_moment", "a_univ",
                             "ks_distance", "ks_pvalue", "mean_area_x", "smallest_resolvable_xi",
                             // the facet law cut at the resolution floor (fits/truncated_shape.hpp)
                             "n_facets_above_floor", "a_fit_above_floor", "a_univ_above_floor",
                             "mean_area_x_above_floor", "law_share_below_floor",
                             "ks_distance_above_floor"};
// The fitted quantities, P first: it is the experiments' measure (docs/STATISTICS.md §2.1).
const char* const kFitQuantities[] = {"perimeter_P", "crease_length_L0"};
constexpr double kKsLevel = 0.05;

EnsembleJson get_or_null(const EnsembleJson& obj, const std::string& key) {
  if (!obj.is_object()) return nullptr;
  const auto it = obj.find(key);
  return it == obj.end() ? EnsembleJson() : *it;
}

/// The run as ensemble.json "runs" holds it: what the plots and the report take from each run.
EnsembleJson run_record(const RunStats& rs) {
  namespace fs = std::filesystem;
  const EnsembleJson& s = rs.stats;
  const EnsembleJson input = get_or_null(s, "input"), par = get_or_null(s, "parameters"),
                     sheet = get_or_null(s, "sheet");
  EnsembleJson cycles = s.at("cycles");
  std::stable_sort(cycles.begin(), cycles.end(), [](const EnsembleJson& a, const EnsembleJson& b) {
    return a.at("cycle").get<int>() < b.at("cycle").get<int>();
  });
  bool has_stages = false;
  for (const auto& c : cycles) {
    const auto st = c.find("stages");
    has_stages = has_stages || (st != c.end() && st->is_array() && !st->empty());
  }
  std::error_code ec;
  const fs::path abs = fs::absolute(fs::path(rs.path), ec);
  return {{"stats_path", rs.path},
          {"analysis_dir", (ec ? fs::path(rs.path) : abs).parent_path().lexically_normal().string()},
          {"seed", get_or_null(get_or_null(input, "meta"), "seed")},
          {"compaction", get_or_null(input, "compaction")},
          {"compaction_note", get_or_null(input, "compaction_note")},
          {"L0_m", get_or_null(sheet, "L0_m")},
          {"px_per_m", get_or_null(sheet, "px_per_m")},
          {"threshold", get_or_null(par, "threshold")},
          {"threshold_rule", get_or_null(par, "threshold_rule")},
          {"threshold_note", get_or_null(par, "threshold_note")},
          {"bootstrap_resamples", get_or_null(par, "bootstrap_resamples")},
          {"resolution", get_or_null(s, "resolution")},
          {"warnings", s.value("warnings", EnsembleJson::array())},
          {"log_fit", get_or_null(s, "log_fit")},
          {"has_stages", has_stages},
          {"threshold_sensitivity", get_or_null(s, "threshold_sensitivity")},
          {"cycles", std::move(cycles)}};
}

/// The compaction ratio of one cycle of one run: the cycle's own (stats.json "cycles[].compaction",
/// read from the run file's /cycles/NNNN@compaction), or for a stats.json from before it was
/// recorded per cycle, the run's input.compaction.
std::optional<double> cycle_compaction(const EnsembleJson& run, const EnsembleJson& cycle) {
  if (cycle.contains("compaction")) return number(cycle, "compaction");
  return number(run, "compaction");
}

/// The distinct values among `v` (null included as nullopt), in order of first appearance.
std::vector<std::optional<double>> distinct(const std::vector<std::optional<double>>& v) {
  std::vector<std::optional<double>> out;
  for (const auto& x : v)
    if (std::find(out.begin(), out.end(), x) == out.end()) out.push_back(x);
  return out;
}

std::string format_number(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

std::string list_values(const std::vector<std::optional<double>>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + (x ? format_number(*x) : "unknown");
  return s;
}

/// The KS test of each run at 5 % (p < 0.05) from the p-value under `p_key`: per run into
/// row[prefix + "_tests"], counted in row[prefix + "_n_tested"], "_n_rejected", "_n_at_floor".
/// A p at the bootstrap floor 1/(B+1) means no resample was as far from the law as the data:
/// p is at most the floor. Entries have `run` and `cycle` (records of ensemble_json).
template <class Entries>
void put_ks_tests(EnsembleJson& row, const Entries& entries, const char* p_key,
                  const std::string& prefix) {
  EnsembleJson ks = EnsembleJson::array();
  int tested = 0, rejected = 0, at_floor_count = 0;
  for (const auto& e : entries) {
    const auto p = number(*e.cycle, p_key);
    const auto B = number(*e.run, "bootstrap_resamples");
    const std::optional<double> floor =
        B && *B != 0 ? std::optional<double>(1.0 / (*B + 1.0)) : std::nullopt;
    const bool at_floor = p && floor && *p <= *floor * (1 + 1e-9);
    const bool rej = p && *p < kKsLevel;
    ks.push_back({{"seed", e.run->at("seed")},
                  {"p", or_null(p)},
                  {"floor", or_null(floor)},
                  {"at_floor", at_floor},
                  {"rejected", rej}});
    tested += p.has_value();
    rejected += rej;
    at_floor_count += at_floor;
  }
  row[prefix + "_tests"] = std::move(ks);
  row[prefix + "_n_tested"] = tested;
  row[prefix + "_n_rejected"] = rejected;
  row[prefix + "_n_at_floor"] = at_floor_count;
}

}  // namespace

EnsembleJson ensemble_fit(LawSeries series, const std::vector<int>& n, const std::vector<double>& y,
                          const std::optional<std::vector<double>>& sigma,
                          const std::optional<double>& D) {
  const bool increments = series == LawSeries::Increments;
  const std::string label =
      increments ? "increments: dy_n = C [ln(1 + n/n0) - ln(1 + (n-1)/n0)]"
                 : "cumulative: y_n = C ln(1 + n/n0) (values correlated between cycles)";
  if (n.size() < 3)
    return {{"model", label}, {"error", "needs at least 3 cycles, have " + std::to_string(n.size())}};
  if (std::none_of(y.begin(), y.end(), [](double v) { return v > 0; }))
    return {{"model", label}, {"error", "no crease length in any cycle"}};
  const bool weighted = sigma.has_value();
  const std::vector<double> to(n.begin(), n.end());
  LogLawFit f;
  try {
    if (increments) {
      std::vector<double> from;
      for (int k : n) from.push_back(k - 1.0);  // the increment of cycle n is y_n - y_(n-1)
      f = fit_log_law_increments(from, to, y, weighted ? *sigma : std::vector<double>{});
    } else {
      f = fit_log_law(to, y, weighted ? *sigma : std::vector<double>{});
    }
  } catch (const std::invalid_argument& e) {
    return {{"model", label}, {"error", e.what()}};
  }
  const auto finite = [](double v) { return std::isfinite(v) ? std::optional<double>(v) : std::nullopt; };
  const std::optional<double> sC = finite(f.sigma_C), sn0 = finite(f.sigma_n0);
  EnsembleJson cycles = EnsembleJson::array(), values = EnsembleJson::array(),
               sigmas = weighted ? EnsembleJson::array() : EnsembleJson();
  for (std::size_t i = 0; i < n.size(); ++i) {
    cycles.push_back(n[i]);
    values.push_back(y[i]);
    if (weighted) sigmas.push_back((*sigma)[i]);
  }
  EnsembleJson out = {
      {"model", label},
      {"method", "least squares, C solved exactly for each n0 and chi2 minimised over ln n0 "
                 "(a scan, then Brent's method) within C >= 0 and 1e-6 <= n0 <= 1e6 "
                 "(analysis/fits/log_law.cpp); covariance " +
                     std::string(weighted ? "(J^T W J)^-1 with the absolute sigmas"
                                          : "s^2 (J^T J)^-1, scaled by the residuals")},
      {"C", or_null(f.C)},
      {"sigma_C", or_null(sC)},
      {"n0", or_null(f.n0)},
      {"sigma_n0", or_null(sn0)},
      {"corr_C_n0", sC && sn0 && *sC > 0 && *sn0 > 0 ? or_null(f.corr) : EnsembleJson()},
      {"chi2", or_null(f.rss)},
      {"dof", f.dof},
      {"weighted", weighted},
      {"converged", f.converged},
      {"iterations", f.iterations},
      {"at_bound", f.at_bound},
      // n0 far outside the cycles fitted (on a bound of the search among them), or an error
      // larger than itself: the data do not fix where the law bends.
      {"n0_poorly_constrained", f.n0 > 1e4 || f.n0 < 1e-5 || !sn0 || *sn0 > f.n0},
      {"cycles", std::move(cycles)},
      {"values", std::move(values)},
      {"sigmas", std::move(sigmas)},
      {"weights_note", weighted ? "weighted by the seed-to-seed s.e.m., each variance averaged "
                                  "half and half with the series' mean variance (moderated)"
                                : "unweighted (no seed-to-seed s.e.m.: fewer than 2 runs or a "
                                  "zero spread); errors scaled by the residuals"}};
  if (D && *D > 0 && *D < 1) {
    const ExperimentConstants k = to_experiment_constants(f, *D);
    out["c1"] = or_null(k.c1);
    out["sigma_c1"] = sC ? or_null(k.sigma_c1) : EnsembleJson();
    out["c2"] = or_null(k.c2);
    out["sigma_c2"] = sn0 ? or_null(k.sigma_c2) : EnsembleJson();
  }
  return out;
}

EnsembleJson ensemble_json(const std::vector<RunStats>& inputs) {
  if (inputs.empty()) throw std::invalid_argument("ensemble_json: no runs");
  std::vector<EnsembleJson> runs;
  for (const auto& r : inputs) runs.push_back(run_record(r));
  EnsembleJson notes = EnsembleJson::array();

  // The compaction ratio: per cycle, the value every run recorded for it; overall, the value of
  // every cycle of every run. c1 and c2 need one value (the experiment's law is for one D).
  std::vector<std::optional<double>> run_values, all_values;
  for (const auto& r : runs) {
    run_values.push_back(number(r, "compaction"));
    for (const auto& c : r.at("cycles")) all_values.push_back(cycle_compaction(r, c));
  }
  const auto all_distinct = distinct(all_values);
  const std::optional<double> compaction =
      all_distinct.size() == 1 ? all_distinct[0] : std::optional<double>();
  std::string compaction_note;
  if (!compaction) {
    const auto per_run = distinct(run_values);
    bool runs_differ = false;
    for (const auto& r : runs) {
      std::vector<std::optional<double>> own;
      for (const auto& c : r.at("cycles")) own.push_back(cycle_compaction(r, c));
      runs_differ = runs_differ || distinct(own).size() > 1;
    }
    if (std::find(all_values.begin(), all_values.end(), std::nullopt) != all_values.end()) {
      compaction_note = "the compaction ratio is unknown for some cycles (";
      std::string why;
      for (const auto& r : runs)
        if (const auto w = r.find("compaction_note"); w != r.end() && w->is_string()) {
          why = w->get<std::string>();
          break;
        }
      compaction_note += why.empty() ? "not recorded in their run files" : why;
      compaction_note += "); c1 and c2 are not computed and no experimental law is drawn";
    } else if (runs_differ) {
      compaction_note = "the compaction ratio differs from cycle to cycle (" +
                        list_values(all_distinct) +
                        "); c1 and c2 need one value and are not computed, and no single "
                        "experimental law is drawn";
    } else {
      compaction_note = "the runs have different compactions (" + list_values(per_run) +
                        "); no experimental law is drawn";
    }
    notes.push_back(compaction_note);
  }

  std::vector<EnsembleJson> thresholds;
  for (const auto& r : runs) {
    const EnsembleJson t = r.at("threshold");
    if (std::find(thresholds.begin(), thresholds.end(), t) == thresholds.end())
      thresholds.push_back(t);
  }
  if (thresholds.size() > 1) {
    std::vector<double> t;
    for (const auto& x : thresholds)
      if (x.is_number()) t.push_back(x.get<double>());
    std::sort(t.begin(), t.end());
    std::string s;
    for (double v : t) s += (s.empty() ? "" : ", ") + format_number(v);
    notes.push_back("the runs use different crease thresholds: [" + s + "]");
  }

  // Per cycle: (run, cycle record, increments of the fitted quantities, a_fit - a_univ).
  struct Entry {
    const EnsembleJson* run;
    const EnsembleJson* cycle;
    std::map<std::string, double> increment;
    std::optional<double> a_diff, a_diff_above_floor;
  };
  std::map<int, std::vector<Entry>> by_cycle;
  for (const auto& r : runs) {
    std::map<int, const EnsembleJson*> index;
    for (const auto& c : r.at("cycles")) index[c.at("cycle").get<int>()] = &c;
    for (const auto& c : r.at("cycles")) {
      const int n = c.at("cycle").get<int>();
      Entry e{&r, &c, {}, std::nullopt, std::nullopt};
      // Before the first cycle the sheet is flat: y_0 = 0. A missing previous cycle leaves the
      // increment undefined rather than spanning two cycles.
      const auto prev = index.find(n - 1);
      for (const char* q : kFitQuantities) {
        const auto now = number(c, q);
        const std::optional<double> before =
            n == 1 ? std::optional<double>(0.0)
                   : (prev != index.end() ? number(*prev->second, q) : std::nullopt);
        if (now && before) e.increment[q] = *now - *before;
      }
      const auto a = number(c, "a_fit"), u = number(c, "a_univ");
      if (a && u) e.a_diff = *a - *u;
      const auto af = number(c, "a_fit_above_floor"), uf = number(c, "a_univ_above_floor");
      if (af && uf) e.a_diff_above_floor = *af - *uf;
      by_cycle[n].push_back(std::move(e));
    }
  }
  EnsembleJson table = EnsembleJson::array();
  for (const auto& [n, entries] : by_cycle) {
    EnsembleJson row = {{"cycle", n}, {"n_runs", entries.size()}};
    std::vector<std::optional<double>> comp;
    for (const auto& e : entries) comp.push_back(cycle_compaction(*e.run, *e.cycle));
    const auto cd = distinct(comp);
    row["compaction"] = cd.size() == 1 ? or_null(cd[0]) : EnsembleJson();
    for (const char* k : kKeys) {
      std::vector<std::optional<double>> v;
      for (const auto& e : entries) v.push_back(number(*e.cycle, k));
      put(row, k, v);
    }
    for (const char* q : kFitQuantities) {
      std::vector<std::optional<double>> v;
      for (const auto& e : entries) {
        const auto it = e.increment.find(q);
        v.push_back(it == e.increment.end() ? std::nullopt : std::optional<double>(it->second));
      }
      put(row, std::string(q) + "_increment", v);
    }
    std::vector<std::optional<double>> d;
    for (const auto& e : entries) d.push_back(e.a_diff);
    put(row, "a_fit_minus_a_univ", d);
    d.clear();
    for (const auto& e : entries) d.push_back(e.a_diff_above_floor);
    put(row, "a_fit_minus_a_univ_above_floor", d);
    // How many runs measured a shape above the floor, and on which edge of the search the
    // others' fits stopped (fits/truncated_shape.hpp FitEdge).
    int n_shape = 0;
    EnsembleJson edges = {{"a_min", 0}, {"a_max", 0}, {"theta", 0}};
    for (const auto& e : entries) {
      n_shape += number(*e.cycle, "a_fit_above_floor").has_value();
      const auto it = e.cycle->find("fit_above_floor_edge");
      if (it != e.cycle->end() && it->is_string() && edges.contains(it->get<std::string>()))
        edges[it->get<std::string>()] = edges[it->get<std::string>()].get<int>() + 1;
    }
    row["a_fit_above_floor_n"] = n_shape;
    row["fit_above_floor_edges"] = std::move(edges);
    put_ks_tests(row, entries, "ks_pvalue", "ks");
    put_ks_tests(row, entries, "ks_pvalue_above_floor", "ks_above_floor");
    table.push_back(std::move(row));
  }

  // The fits to the ensemble means, weighted by their s.e.m. when every cycle has one (a zero
  // or missing spread would give a point infinite weight), moderated (moderated_sems: a
  // three-seed s.e.m. small by chance would otherwise carry the fit).
  const auto series = [&](const std::string& key, std::vector<int>& n, std::vector<double>& y,
                          std::optional<std::vector<double>>& sigma) {
    std::vector<double> s;
    bool all_positive = true;
    for (const auto& row : table) {
      const auto m = number(row, key + "_mean");
      if (!m) continue;
      n.push_back(row.at("cycle").get<int>());
      y.push_back(*m);
      const auto e = number(row, key + "_sem");
      all_positive = all_positive && e && *e > 0;
      s.push_back(e.value_or(0.0));
    }
    if (all_positive) sigma = moderated_sems(s);
  };
  EnsembleJson fits = EnsembleJson::object();
  for (const char* q : kFitQuantities) {
    std::vector<int> ni, nc;
    std::vector<double> yi, yc;
    std::optional<std::vector<double>> si, sc;
    series(std::string(q) + "_increment", ni, yi, si);
    series(q, nc, yc, sc);
    fits[q] = {{"increments", ensemble_fit(LawSeries::Increments, ni, yi, si, compaction)},
               {"cumulative", ensemble_fit(LawSeries::Cumulative, nc, yc, sc, compaction)}};
  }
  fits["note"] = "increments: primary (errors from the seed-to-seed s.e.m. of each cycle's "
                 "increment; increments of different cycles are close to independent). "
                 "cumulative: the same law on the cumulative means; their errors are correlated "
                 "between cycles, so its chi2/dof and errors are too optimistic.";

  std::vector<EnsembleJson> rules, Bs;
  for (const auto& r : runs) {
    for (auto [list, key] : {std::pair{&rules, "threshold_rule"}, std::pair{&Bs, "bootstrap_resamples"}}) {
      const EnsembleJson v = r.at(key);
      if (std::find(list->begin(), list->end(), v) == list->end()) list->push_back(v);
    }
  }
  EnsembleJson seeds = EnsembleJson::array();
  for (const auto& r : runs) seeds.push_back(r.at("seed"));
  EnsembleJson out;
  out["compaction"] = or_null(compaction);
  out["compaction_note"] = compaction_note.empty() ? EnsembleJson() : EnsembleJson(compaction_note);
  out["n_runs"] = runs.size();
  out["seeds"] = std::move(seeds);
  out["notes"] = std::move(notes);
  out["parameters"] = {{"threshold", thresholds.size() == 1 ? thresholds[0] : EnsembleJson()},
                       {"threshold_rule", rules.size() == 1 ? rules[0] : EnsembleJson()},
                       {"threshold_note", runs[0].at("threshold_note")},
                       {"bootstrap_resamples", Bs.size() == 1 ? Bs[0] : EnsembleJson()},
                       {"ks_level", kKsLevel}};
  out["stages"] = stage_table(runs);
  out["threshold_sensitivity"] = sensitivity_table(runs);
  out["cycles"] = std::move(table);
  out["fits"] = std::move(fits);
  out["runs"] = std::move(runs);
  return out;
}

void write_ensemble(const std::string& path, const EnsembleJson& doc) {
  namespace fs = std::filesystem;
  const fs::path p(path);
  if (p.has_parent_path()) fs::create_directories(p.parent_path());
  const fs::path tmp = p.string() + "." + std::to_string(::getpid()) + ".tmp";
  {
    std::ofstream f(tmp);
    f << doc.dump(2) << "\n";
    f.close();
    if (!f) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw std::runtime_error("cannot write " + tmp.string());
    }
  }
  fs::rename(tmp, p);
}

}  // namespace crumple::analysis
