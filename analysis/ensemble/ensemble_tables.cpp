// The per-stage and threshold-sensitivity tables of the ensemble; see ensemble_tables.hpp.
#include "analysis/ensemble/ensemble_tables.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace crumple::analysis::ensemble_detail {

std::optional<double> number(const EnsembleJson& obj, const std::string& key) {
  if (!obj.is_object()) return std::nullopt;
  const auto it = obj.find(key);
  if (it == obj.end() || !it->is_number()) return std::nullopt;
  return it->get<double>();
}

EnsembleJson or_null(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? EnsembleJson(*v) : EnsembleJson();
}

SampleStats put(EnsembleJson& row, const std::string& key,
                const std::vector<std::optional<double>>& values) {
  const SampleStats s = sample_stats(values);
  row[key + "_mean"] = or_null(s.mean);
  row[key + "_std"] = or_null(s.sd);
  row[key + "_sem"] = or_null(s.sem);
  return s;
}

namespace {

const EnsembleJson& stages_of(const EnsembleJson& cycle) {
  static const EnsembleJson none = EnsembleJson::array();
  const auto it = cycle.find("stages");
  return it != cycle.end() && it->is_array() ? *it : none;
}

}  // namespace

EnsembleJson stage_table(const std::vector<EnsembleJson>& runs) {
  std::vector<const EnsembleJson*> with;
  for (const auto& r : runs)
    if (r.value("has_stages", false)) with.push_back(&r);
  EnsembleJson out = {{"available", !with.empty()},
                      {"n_runs_with_stages", with.size()},
                      {"cycles", EnsembleJson::array()}};
  if (with.empty()) {
    out["note"] = "no per-stage data: the stats.json files have no 'stages' lists (run files "
                  "without /stage_ends, or an older crumple-analyze)";
    return out;
  }
  if (with.size() < runs.size())
    out["note"] = "per-stage data in " + std::to_string(with.size()) + " of " +
                  std::to_string(runs.size()) + " runs; the statistics below use those runs only";
  std::map<int, std::vector<const EnsembleJson*>> by_cycle;
  for (const EnsembleJson* r : with)
    for (const auto& c : r->at("cycles")) by_cycle[c.at("cycle").get<int>()].push_back(&c);
  for (const auto& [n, cs] : by_cycle) {
    // Stages are keyed by (position in the cycle, type): a protocol may repeat a type.
    std::set<std::pair<int, std::string>> keys;
    for (const EnsembleJson* c : cs)
      for (const auto& st : stages_of(*c))
        keys.insert({st.at("index").get<int>(), st.at("stage").get<std::string>()});
    EnsembleJson rows = EnsembleJson::array();
    for (const auto& [idx, name] : keys) {
      std::vector<std::optional<double>> fresh, cumulative, lost;
      int present = 0;
      for (const EnsembleJson* c : cs) {
        const auto& sts = stages_of(*c);
        const auto it = std::find_if(sts.begin(), sts.end(), [&, idx = idx, &name = name](auto& s) {
          return s.at("index").template get<int>() == idx &&
                 s.at("stage").template get<std::string>() == name;
        });
        if (it == sts.end()) continue;
        ++present;
        fresh.push_back(number(*it, "new_crease_length_L0"));
        cumulative.push_back(number(*it, "crease_length_L0"));
        lost.push_back(number(*it, "lost_crease_length_L0"));  // absent in older stats.json
      }
      EnsembleJson row = {{"index", idx}, {"stage", name}};
      put(row, "new_crease_length_L0", fresh);
      put(row, "crease_length_L0", cumulative);
      put(row, "lost_crease_length_L0", lost);
      row["n_runs"] = present;
      rows.push_back(std::move(row));
    }
    EnsembleJson entry = {{"cycle", n}, {"stages", std::move(rows)}};
    std::vector<std::optional<double>> shares, fresh;
    EnsembleJson values = EnsembleJson::array();
    std::optional<double> largest;
    for (const EnsembleJson* c : cs) {
      const auto s = number(*c, "new_length_share_after_compress");
      shares.push_back(s);
      values.push_back(or_null(s));
      if (s) largest = std::max(largest.value_or(*s), *s);
      fresh.push_back(number(*c, "new_crease_length_L0"));
    }
    put(entry, "share_after_compress", shares);
    entry["share_after_compress_max"] = or_null(largest);
    entry["share_after_compress_values"] = std::move(values);
    put(entry, "new_crease_length_L0", fresh);
    out["cycles"].push_back(std::move(entry));
  }
  return out;
}

namespace {

/// A threshold of the sensitivity table: by its factor of c0 when the run gives the factors,
/// else by its absolute value; rounded so that runs of one protocol share the key.
struct ThresholdKey {
  bool is_factor = true;
  double value = 0;
  bool operator==(const ThresholdKey& o) const { return is_factor == o.is_factor && value == o.value; }
};

double round_to(double v, int digits) {
  const double s = std::pow(10.0, digits);
  return std::round(v * s) / s;
}

std::vector<ThresholdKey> keys_of(const EnsembleJson& ts) {
  const EnsembleJson f = ts.value("factors_of_c0", EnsembleJson::array());
  const EnsembleJson t = ts.value("thresholds", EnsembleJson::array());
  std::vector<ThresholdKey> out;
  const bool by_factor = f.is_array() && !f.empty() && t.is_array() && f.size() == t.size();
  for (const auto& x : by_factor ? f : t)
    out.push_back({by_factor, round_to(x.get<double>(), by_factor ? 6 : 9)});
  return out;
}

}  // namespace

EnsembleJson sensitivity_table(const std::vector<EnsembleJson>& runs) {
  std::vector<const EnsembleJson*> have;
  for (const auto& r : runs) {
    const auto it = r.find("threshold_sensitivity");
    if (it != r.end() && it->is_object() && !it->empty()) have.push_back(&r);
  }
  EnsembleJson out = {{"available", !have.empty()},
                      {"n_runs", have.size()},
                      {"cycles", EnsembleJson::array()}};
  if (have.empty()) {
    out["note"] = "no threshold-sensitivity data: the stats.json files have no "
                  "'threshold_sensitivity' (older crumple-analyze)";
    return out;
  }
  std::vector<ThresholdKey> all;
  for (const EnsembleJson* r : have)
    for (const auto& k : keys_of(r->at("threshold_sensitivity")))
      if (std::find(all.begin(), all.end(), k) == all.end()) all.push_back(k);
  std::stable_sort(all.begin(), all.end(),
                   [](const ThresholdKey& a, const ThresholdKey& b) { return a.value < b.value; });
  const auto slot = [&](const ThresholdKey& k) {
    return static_cast<std::size_t>(std::find(all.begin(), all.end(), k) - all.begin());
  };
  out["key_kind"] = all.empty() ? EnsembleJson() : EnsembleJson(all[0].is_factor ? "factor" : "threshold");
  EnsembleJson factors = EnsembleJson::array();
  for (const auto& k : all) factors.push_back(k.is_factor ? EnsembleJson(k.value) : EnsembleJson());
  out["factors_of_c0"] = std::move(factors);

  // values[slot] per threshold; per cycle the l, P and facet-count values of every run
  struct Values {
    std::vector<std::vector<std::optional<double>>> l, P, nf;
  };
  std::vector<std::vector<std::optional<double>>> thresholds(all.size());
  std::map<int, Values> data;
  for (const EnsembleJson* r : have) {
    const EnsembleJson& ts = r->at("threshold_sensitivity");
    const auto ks = keys_of(ts);
    const EnsembleJson t = ts.value("thresholds", EnsembleJson::array());
    for (std::size_t i = 0; i < ks.size() && i < t.size(); ++i)
      thresholds[slot(ks[i])].push_back(t[i].get<double>());
    for (const auto& c : ts.value("cycles", EnsembleJson::array())) {
      Values& d = data.try_emplace(c.at("cycle").get<int>(),
                                   Values{std::vector<std::vector<std::optional<double>>>(all.size()),
                                          std::vector<std::vector<std::optional<double>>>(all.size()),
                                          std::vector<std::vector<std::optional<double>>>(all.size())})
                      .first->second;
      for (std::size_t i = 0; i < ks.size(); ++i)
        for (const auto& [src, dst] : {std::pair{"crease_length_L0", &d.l},
                                       std::pair{"perimeter_P", &d.P},
                                       std::pair{"n_facets", &d.nf}}) {
          const EnsembleJson v = c.value(src, EnsembleJson::array());
          if (v.is_array() && i < v.size())
            (*dst)[slot(ks[i])].push_back(v[i].is_number() ? std::optional<double>(v[i].get<double>())
                                                           : std::nullopt);
        }
    }
  }
  EnsembleJson means = EnsembleJson::array(), spreads = EnsembleJson::array();
  for (const auto& t : thresholds) {
    means.push_back(or_null(sample_stats(t).mean));
    std::optional<double> lo, hi;
    for (const auto& v : t)
      if (v) lo = std::min(lo.value_or(*v), *v), hi = std::max(hi.value_or(*v), *v);
    spreads.push_back(lo ? EnsembleJson::array({*lo, *hi}) : EnsembleJson());
  }
  out["thresholds_mean"] = std::move(means);
  out["thresholds_spread"] = std::move(spreads);
  // The factor the runs' own threshold used, when they all used the same one.
  std::vector<EnsembleJson> used;
  for (const auto& r : runs) {
    const auto rule = r.value("threshold_rule", EnsembleJson());
    const EnsembleJson f = rule.is_object() ? rule.value("factor", EnsembleJson()) : EnsembleJson();
    if (std::find(used.begin(), used.end(), f) == used.end()) used.push_back(f);
  }
  out["used_factor"] = used.size() == 1 ? used[0] : EnsembleJson();
  for (const auto& [n, d] : data) {
    EnsembleJson entry = {{"cycle", n}};
    for (const auto& [name, v] : {std::pair{"crease_length_L0", &d.l},
                                  std::pair{"perimeter_P", &d.P}, std::pair{"n_facets", &d.nf}}) {
      EnsembleJson m = EnsembleJson::array(), s = EnsembleJson::array();
      for (const auto& vals : *v) {
        const SampleStats st = sample_stats(vals);
        m.push_back(or_null(st.mean));
        s.push_back(or_null(st.sem));
      }
      entry[std::string(name) + "_mean"] = std::move(m);
      entry[std::string(name) + "_sem"] = std::move(s);
    }
    out["cycles"].push_back(std::move(entry));
  }
  return out;
}

std::vector<double> moderated_sems(const std::vector<double>& sems) {
  if (sems.empty()) return {};
  double mean_var = 0;
  for (double s : sems) mean_var += s * s;
  mean_var /= static_cast<double>(sems.size());
  std::vector<double> out;
  out.reserve(sems.size());
  for (double s : sems) out.push_back(std::sqrt(0.5 * (s * s + mean_var)));
  return out;
}

}  // namespace crumple::analysis::ensemble_detail
