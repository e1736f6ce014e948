// The ensemble over runs (analysis/ensemble/): sample statistics; per-cycle means, s.d. and
// s.e.m. of stats.json documents built here, against sums computed here; the log-law fits to
// the ensemble means (weights, absolute-sigma convention, unweighted fallback, too few cycles);
// the compaction the runs agree on per cycle and overall; the KS tallies, the per-stage and the
// threshold-sensitivity tables; `crumple-analyze ensemble` end to end; the collapse over
// ensembles of several compaction ratios (`crumple-analyze collapse`).
#include "analysis/ensemble/collapse.hpp"
#include "analysis/ensemble/ensemble.hpp"
#include "analysis/ensemble/ensemble_tables.hpp"
#include "analysis/fits/log_law.hpp"
#include "analysis/io/run_reader.hpp"
#include "tests/analysis/synthetic_run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>

namespace fs = std::filesystem;
using namespace crumple::analysis;
using J = EnsembleJson;

namespace {

double law(double n, double C, double n0) { return C * std::log1p(n / n0); }

/// mean, s.d. and s.e.m. written out for the test, independent of sample_stats.
struct Expected {
  double mean, sd, sem;
};
Expected expected(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m += x;
  m /= static_cast<double>(v.size());
  double ss = 0;
  for (double x : v) ss += (x - m) * (x - m);
  const double sd = std::sqrt(ss / static_cast<double>(v.size() - 1));
  return {m, sd, sd / std::sqrt(static_cast<double>(v.size()))};
}

/// A stats.json document of one run: P_n and l_n/L0 per cycle, with the given compaction per
/// cycle (a per-cycle key; omitted with `per_cycle_compaction` false, as older stats.json).
J stats_doc(int seed, const std::vector<double>& P, const std::vector<double>& l,
            std::optional<double> D, bool per_cycle_compaction = true,
            const std::vector<std::optional<double>>& cycle_D = {}) {
  J cycles = J::array();
  for (std::size_t i = 0; i < P.size(); ++i) {
    J c = {{"cycle", static_cast<int>(i + 1)}, {"perimeter_P", P[i]}, {"crease_length_L0", l[i]}};
    if (per_cycle_compaction) {
      const std::optional<double> d = i < cycle_D.size() ? cycle_D[i] : D;
      c["compaction"] = d ? J(*d) : J();
    }
    cycles.push_back(c);
  }
  return {{"input", {{"meta", {{"seed", seed}}}, {"compaction", D ? J(*D) : J()}}},
          {"parameters", {{"threshold", 0.15}, {"bootstrap_resamples", 99}}},
          {"cycles", cycles}};
}

std::vector<RunStats> as_runs(const std::vector<J>& docs) {
  std::vector<RunStats> out;
  for (std::size_t i = 0; i < docs.size(); ++i)
    out.push_back({"runs/seed" + std::to_string(i + 1) + ".analysis/stats.json", docs[i]});
  return out;
}

/// chi^2 of the increment law at (C, n0) against means y with errors s at cycles 1..N.
double chi2_increments(const std::vector<double>& y, const std::vector<double>& s, double C,
                       double n0) {
  double r = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double n = static_cast<double>(i + 1);
    const double d = (y[i] - (law(n, C, n0) - law(n - 1, C, n0))) / s[i];
    r += d * d;
  }
  return r;
}

}  // namespace

TEST(Ensemble, SampleStatistics) {
  const SampleStats s = sample_stats({1.0, 2.0, std::nullopt, 4.0, NAN});
  const Expected e = expected({1.0, 2.0, 4.0});
  EXPECT_EQ(s.n, 3);
  EXPECT_DOUBLE_EQ(*s.mean, e.mean);
  EXPECT_DOUBLE_EQ(*s.sd, e.sd);
  EXPECT_DOUBLE_EQ(*s.sem, e.sem);
  const SampleStats one = sample_stats({2.5});
  EXPECT_EQ(one.mean, 2.5);
  EXPECT_FALSE(one.sd || one.sem);  // no spread from one value
  const SampleStats none = sample_stats({std::nullopt});
  EXPECT_EQ(none.n, 0);
  EXPECT_FALSE(none.mean);
}

// Seeds scattered about the law with offsets that cancel in every cycle: the ensemble mean is
// the law itself, so the weighted fits recover (C, n0) and c1, c2 follow from the compaction.
TEST(Ensemble, PerCycleStatisticsAndFitsRecoverTheLaw) {
  const double C = 8.0, n0 = 2.2, D = 0.27;
  const int N = 6;
  const std::vector<double> offset = {0.3, -0.1, -0.2};  // sums to zero
  std::vector<J> docs;
  std::vector<std::vector<double>> P(3), l(3);
  for (int s = 0; s < 3; ++s) {
    for (int n = 1; n <= N; ++n) {
      P[s].push_back(law(n, C, n0) + offset[s] * (1 + 0.1 * n));
      l[s].push_back(2.0 * law(n, C, n0) + offset[(s + 1) % 3] * n);
    }
    docs.push_back(stats_doc(s + 1, P[s], l[s], D));
  }
  const J e = ensemble_json(as_runs(docs));
  EXPECT_EQ(e["n_runs"], 3);
  EXPECT_EQ(e["compaction"].get<double>(), D);
  EXPECT_TRUE(e["compaction_note"].is_null());
  ASSERT_EQ(e["cycles"].size(), static_cast<std::size_t>(N));
  for (int i = 0; i < N; ++i) {
    const J& row = e["cycles"][i];
    EXPECT_EQ(row["cycle"], i + 1);
    EXPECT_EQ(row["n_runs"], 3);
    EXPECT_EQ(row["compaction"].get<double>(), D);
    const Expected p = expected({P[0][i], P[1][i], P[2][i]});
    EXPECT_DOUBLE_EQ(row["perimeter_P_mean"].get<double>(), p.mean);
    EXPECT_DOUBLE_EQ(row["perimeter_P_std"].get<double>(), p.sd);
    EXPECT_DOUBLE_EQ(row["perimeter_P_sem"].get<double>(), p.sem);
    std::vector<double> inc;
    for (int s = 0; s < 3; ++s) inc.push_back(P[s][i] - (i ? P[s][i - 1] : 0.0));
    const Expected d = expected(inc);
    EXPECT_NEAR(row["perimeter_P_increment_mean"].get<double>(), d.mean, 1e-12);
    EXPECT_NEAR(row["perimeter_P_increment_sem"].get<double>(), d.sem, 1e-12);
    EXPECT_TRUE(row["a_fit_mean"].is_null());  // not in these documents
  }
  for (const char* q : {"perimeter_P", "crease_length_L0"}) {
    const double scale = std::string(q) == "perimeter_P" ? 1.0 : 2.0;
    for (const char* kind : {"increments", "cumulative"}) {
      SCOPED_TRACE(std::string(q) + " " + kind);
      const J& f = e["fits"][q][kind];
      ASSERT_FALSE(f.contains("error")) << f.dump();
      EXPECT_TRUE(f["weighted"].get<bool>());
      EXPECT_NEAR(f["C"].get<double>(), scale * C, 1e-6 * C);
      EXPECT_NEAR(f["n0"].get<double>(), n0, 1e-6 * n0);
      EXPECT_EQ(f["dof"], N - 2);
      EXPECT_NEAR(f["chi2"].get<double>(), 0.0, 1e-10);
      EXPECT_NEAR(f["c1"].get<double>(), f["C"].get<double>() / (1 - D), 1e-12);
      EXPECT_NEAR(f["c2"].get<double>(), D / f["n0"].get<double>(), 1e-12);
      EXPECT_NEAR(f["sigma_c1"].get<double>(), f["sigma_C"].get<double>() / (1 - D), 1e-12);
      EXPECT_FALSE(f["n0_poorly_constrained"].get<bool>());
      // The weights are the s.e.m. of the very series fitted, each variance averaged half and
      // half with the series' mean variance (moderated_sems).
      const std::string key = std::string(q) + (std::string(kind) == "increments" ? "_increment" : "");
      double mean_var = 0;
      for (int i = 0; i < N; ++i) mean_var += std::pow(e["cycles"][i][key + "_sem"].get<double>(), 2) / N;
      for (int i = 0; i < N; ++i) {
        const double s = e["cycles"][i][key + "_sem"].get<double>();
        EXPECT_NEAR(f["sigmas"][i].get<double>(), std::sqrt(0.5 * (s * s + mean_var)), 1e-12 * s);
      }
    }
  }
}

// A three-seed s.e.m. can be small by chance: with every other cycle's s.e.m. 2 and one
// cycle's 0.02 (its seeds agreeing to 1 %), that cycle would carry 10^4 times the weight of any
// other and the fit would pass through it. Moderated, the weights keep their order, no point
// weighs more than twice one at the mean variance, and a fit whose chance-small point lies off
// the law stays near the fit with equal weights instead of being pinned to that point.
TEST(Ensemble, ModeratedSemsBoundAChanceSmallOne) {
  using crumple::analysis::ensemble_detail::moderated_sems;
  const std::vector<double> s = {2.0, 3.0, 2.0, 0.02, 2.5};
  const std::vector<double> m = moderated_sems(s);
  ASSERT_EQ(m.size(), s.size());
  double mean_var = 0;
  for (double x : s) mean_var += x * x / s.size();
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_NEAR(m[i] * m[i], 0.5 * (s[i] * s[i] + mean_var), 1e-12);
    EXPECT_GE(m[i] * m[i], 0.5 * mean_var);  // weight at most twice the mean variance's
    for (std::size_t j = 0; j < s.size(); ++j) {
      if (s[i] < s[j]) {
        EXPECT_LT(m[i], m[j]);  // order kept
      }
    }
  }
  EXPECT_TRUE(moderated_sems({}).empty());
  const std::vector<double> equal = moderated_sems({1.5, 1.5, 1.5});
  for (double x : equal) EXPECT_NEAR(x, 1.5, 1e-15);  // equal s.e.m. are left as they are

  // Increments on the law C [ln(1 + n/n0) - ln(1 + (n-1)/n0)] with C = 38, n0 = 2.7, except
  // cycle 8, 40 % low with the chance-small s.e.m.
  std::vector<int> n;
  std::vector<double> y, raw;
  for (int k = 1; k <= 10; ++k) {
    n.push_back(k);
    y.push_back(38.0 * (std::log1p(k / 2.7) - std::log1p((k - 1) / 2.7)) * (k == 8 ? 0.6 : 1.0));
    raw.push_back(k == 8 ? 0.02 : 2.0);
  }
  const J pinned = ensemble_fit(LawSeries::Increments, n, y, raw, std::nullopt);
  const J moderated = ensemble_fit(LawSeries::Increments, n, y, moderated_sems(raw), std::nullopt);
  const J equal_w = ensemble_fit(LawSeries::Increments, n, y, std::vector<double>(10, 2.0), std::nullopt);
  const auto C = [](const J& f) { return f["C"].get<double>(); };
  // Raw weights drag C far from the equal-weight fit; moderated, it stays within 10 % of it.
  EXPECT_GT(std::abs(C(pinned) - C(equal_w)), 0.2 * C(equal_w));
  EXPECT_LT(std::abs(C(moderated) - C(equal_w)), 0.1 * C(equal_w));
}

// Means off the law: the fit is the minimum of chi^2 = sum ((y - model)/sem)^2 (weighted least
// squares), and the sems are absolute errors: doubling them all leaves (C, n0), doubles their
// errors and quarters chi^2 (scipy's absolute_sigma=True, which ensemble.py used).
TEST(Ensemble, WeightedFitIsTheChi2MinimumWithAbsoluteSigmas) {
  const std::vector<double> y = {5.1, 2.6, 1.9, 1.3, 1.2, 0.8}, s = {0.4, 0.2, 0.3, 0.1, 0.2, 0.15};
  std::vector<int> n = {1, 2, 3, 4, 5, 6};
  const J f = ensemble_fit(LawSeries::Increments, n, y, s, std::nullopt);
  ASSERT_FALSE(f.contains("error")) << f.dump();
  const double C = f["C"].get<double>(), n0 = f["n0"].get<double>();
  const double best = chi2_increments(y, s, C, n0);
  EXPECT_NEAR(f["chi2"].get<double>(), best, 1e-9 * best);
  for (double dc : {-1e-3, 1e-3})
    for (double dn : {-1e-3, 0.0, 1e-3})
      EXPECT_GT(chi2_increments(y, s, C * (1 + dc), n0 * (1 + dn)), best) << dc << " " << dn;
  EXPECT_FALSE(f.contains("c1"));  // no compaction given
  std::vector<double> s2;
  for (double v : s) s2.push_back(2 * v);
  const J g = ensemble_fit(LawSeries::Increments, n, y, s2, std::nullopt);
  EXPECT_NEAR(g["C"].get<double>(), C, 1e-7 * C);
  EXPECT_NEAR(g["n0"].get<double>(), n0, 1e-6 * n0);
  EXPECT_NEAR(g["sigma_C"].get<double>(), 2 * f["sigma_C"].get<double>(), 1e-6 * f["sigma_C"].get<double>());
  EXPECT_NEAR(g["sigma_n0"].get<double>(), 2 * f["sigma_n0"].get<double>(), 1e-5 * f["sigma_n0"].get<double>());
  EXPECT_NEAR(g["chi2"].get<double>(), best / 4, 1e-8 * best);
  // Without sigmas: unweighted, errors scaled by the residuals, so scaling y scales them.
  const J u = ensemble_fit(LawSeries::Increments, n, y, std::nullopt, 0.5);
  EXPECT_FALSE(u["weighted"].get<bool>());
  EXPECT_TRUE(u["sigmas"].is_null());
  EXPECT_NE(u["weights_note"].get<std::string>().find("unweighted"), std::string::npos);
  std::vector<double> y3;
  for (double v : y) y3.push_back(3 * v);
  const J u3 = ensemble_fit(LawSeries::Increments, n, y3, std::nullopt, 0.5);
  EXPECT_NEAR(u3["sigma_C"].get<double>(), 3 * u["sigma_C"].get<double>(), 1e-6 * u["sigma_C"].get<double>());
  EXPECT_NEAR(u["c2"].get<double>(), 0.5 / u["n0"].get<double>(), 1e-12);
  // Too few cycles, or no crease length: the reason instead of numbers.
  const J few = ensemble_fit(LawSeries::Cumulative, {1, 2}, {1.0, 1.5}, std::nullopt, 0.5);
  EXPECT_EQ(few["error"], "needs at least 3 cycles, have 2");
  EXPECT_FALSE(few.contains("C"));
  const J flat = ensemble_fit(LawSeries::Cumulative, {1, 2, 3}, {0.0, 0.0, 0.0}, std::nullopt, 0.5);
  EXPECT_EQ(flat["error"], "no crease length in any cycle");
}

// One run: no seed-to-seed spread, so the fits are unweighted; a cycle missing in one run has
// no increment there (it does not span two cycles).
TEST(Ensemble, OneRunIsUnweightedAndGapsHaveNoIncrement) {
  std::vector<double> P, l;
  for (int n = 1; n <= 5; ++n) P.push_back(law(n, 6.0, 1.5) * (1 + 0.02 * (n % 2))), l.push_back(2 * P.back());
  const J one = ensemble_json(as_runs({stats_doc(1, P, l, 0.3)}));
  const J& f = one["fits"]["perimeter_P"]["increments"];
  EXPECT_FALSE(f["weighted"].get<bool>());
  EXPECT_TRUE(one["cycles"][0]["perimeter_P_sem"].is_null());
  // the same run fitted directly, unweighted, by the per-run fit
  std::vector<double> from, to, d;
  for (int n = 1; n <= 5; ++n) from.push_back(n - 1), to.push_back(n), d.push_back(P[n - 1] - (n > 1 ? P[n - 2] : 0));
  const LogLawFit direct = fit_log_law_increments(from, to, d);
  EXPECT_NEAR(f["C"].get<double>(), direct.C, 1e-12 * direct.C);
  EXPECT_NEAR(f["sigma_n0"].get<double>(), direct.sigma_n0, 1e-12 * direct.sigma_n0);

  J gap = stats_doc(2, P, l, 0.3);
  gap["cycles"].erase(2);  // cycle 3 missing
  const J two = ensemble_json(as_runs({stats_doc(1, P, l, 0.3), gap}));
  EXPECT_EQ(two["cycles"][2]["n_runs"], 1);
  EXPECT_EQ(two["cycles"][3]["n_runs"], 2);
  // cycle 4's increment exists in run 1 only: mean of one value, no s.e.m.
  EXPECT_NEAR(two["cycles"][3]["perimeter_P_increment_mean"].get<double>(), P[3] - P[2], 1e-12);
  EXPECT_TRUE(two["cycles"][3]["perimeter_P_increment_sem"].is_null());
}

TEST(Ensemble, CompactionTheRunsAgreeOn) {
  const std::vector<double> P = {1, 1.8, 2.4}, l = {2, 3.6, 4.8};
  // Older stats.json: no per-cycle key; the run's input.compaction stands for every cycle.
  J e = ensemble_json(as_runs({stats_doc(1, P, l, 0.27, false), stats_doc(2, P, l, 0.27, false)}));
  EXPECT_EQ(e["compaction"].get<double>(), 0.27);
  EXPECT_TRUE(e["notes"].empty());
  // Runs at different compactions: none, with the note the report prints.
  e = ensemble_json(as_runs({stats_doc(1, P, l, 0.27), stats_doc(2, P, l, 0.36)}));
  EXPECT_TRUE(e["compaction"].is_null());
  EXPECT_TRUE(e["cycles"][0]["compaction"].is_null());
  ASSERT_EQ(e["notes"].size(), 1u);
  EXPECT_NE(e["notes"][0].get<std::string>().find("different compactions"), std::string::npos);
  EXPECT_FALSE(e["fits"]["perimeter_P"]["cumulative"].contains("c1"));
  // A protocol whose compaction changes from cycle to cycle: per cycle yes, overall no.
  const std::vector<std::optional<double>> steps = {0.4, 0.4, 0.2};
  e = ensemble_json(as_runs({stats_doc(1, P, l, std::nullopt, true, steps),
                             stats_doc(2, P, l, std::nullopt, true, steps)}));
  EXPECT_EQ(e["cycles"][0]["compaction"].get<double>(), 0.4);
  EXPECT_EQ(e["cycles"][2]["compaction"].get<double>(), 0.2);
  EXPECT_TRUE(e["compaction"].is_null());
  EXPECT_NE(e["compaction_note"].get<std::string>().find("differs from cycle to cycle"),
            std::string::npos);
  EXPECT_FALSE(e["fits"]["perimeter_P"]["cumulative"].contains("c1"));
  // Not recorded: the run's own note is passed on.
  J old = stats_doc(1, P, l, std::nullopt);
  old["input"]["compaction_note"] = "the run file records no compaction ratio";
  e = ensemble_json(as_runs({old}));
  EXPECT_TRUE(e["compaction"].is_null());
  EXPECT_NE(e["compaction_note"].get<std::string>().find("records no compaction ratio"),
            std::string::npos);
}

TEST(Ensemble, KsTalliesStagesAndSensitivity) {
  std::vector<J> docs;
  const double share[] = {0.1, 0.3};
  const double ks_p[] = {0.01, 0.5};  // B = 99: the floor is 0.01
  for (int s = 0; s < 2; ++s) {
    J d = stats_doc(s + 1, {1.0, 2.0}, {2.0, 4.0}, 0.27);
    for (int i = 0; i < 2; ++i) {
      J& c = d["cycles"][i];
      c["ks_pvalue"] = ks_p[s];
      c["a_fit"] = 1.0 + s;
      c["a_univ"] = 0.5;
      // Above the floor: seed 1 measured a shape (p = 0.2), seed 2's fit ran to its edge (its
      // shape null, its KS p = 0.03 still a test).
      c["ks_pvalue_above_floor"] = s == 0 ? 0.2 : 0.03;
      c["a_fit_above_floor"] = s == 0 ? J(2.0) : J();
      c["a_univ_above_floor"] = s == 0 ? J(1.5) : J();
      c["fit_above_floor_edge"] = s == 0 ? J() : J("a_min");
      c["new_length_share_after_compress"] = share[s];
      c["stages"] = J::array({{{"index", 0}, {"stage", "roll"}, {"new_crease_length_L0", 0.0},
                               {"crease_length_L0", 0.0}, {"lost_crease_length_L0", 0.0}},
                              {{"index", 1}, {"stage", "compress"},
                               {"new_crease_length_L0", 1.0 + s}, {"crease_length_L0", 2.0 * (i + 1)},
                               {"lost_crease_length_L0", 0.0}}});
    }
    d["parameters"]["threshold_rule"] = {{"kind", "fraction_of_c0"}, {"factor", 0.5}};
    d["threshold_sensitivity"] = {
        {"factors_of_c0", {0.5, 1.0}},
        {"thresholds", {0.15, 0.3}},
        {"cycles", J::array({{{"cycle", 1}, {"crease_length_L0", {4.0 + s, 2.0}},
                              {"perimeter_P", {3.0, 1.0 + s}}, {"n_facets", {10, 4}}}})}};
    docs.push_back(d);
  }
  const J e = ensemble_json(as_runs(docs));
  const J& row = e["cycles"][0];
  EXPECT_EQ(row["ks_n_tested"], 2);
  EXPECT_EQ(row["ks_n_rejected"], 1);
  EXPECT_EQ(row["ks_n_at_floor"], 1);
  EXPECT_TRUE(row["ks_tests"][0]["at_floor"].get<bool>());
  EXPECT_DOUBLE_EQ(row["a_fit_minus_a_univ_mean"].get<double>(), expected({0.5, 1.5}).mean);
  EXPECT_DOUBLE_EQ(row["a_fit_minus_a_univ_sem"].get<double>(), expected({0.5, 1.5}).sem);
  EXPECT_EQ(row["ks_above_floor_n_tested"], 2);
  EXPECT_EQ(row["ks_above_floor_n_rejected"], 1);
  EXPECT_EQ(row["ks_above_floor_n_at_floor"], 0);
  EXPECT_TRUE(row["ks_above_floor_tests"][1]["rejected"].get<bool>());
  EXPECT_EQ(row["a_fit_above_floor_n"], 1);
  EXPECT_EQ(row["fit_above_floor_edges"]["a_min"], 1);
  EXPECT_EQ(row["fit_above_floor_edges"]["a_max"], 0);
  EXPECT_DOUBLE_EQ(row["a_fit_above_floor_mean"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(row["a_fit_minus_a_univ_above_floor_mean"].get<double>(), 0.5);

  const J& st = e["stages"];
  EXPECT_TRUE(st["available"].get<bool>());
  ASSERT_EQ(st["cycles"].size(), 2u);
  const J& c2 = st["cycles"][1];
  ASSERT_EQ(c2["stages"].size(), 2u);
  EXPECT_EQ(c2["stages"][1]["stage"], "compress");
  EXPECT_DOUBLE_EQ(c2["stages"][1]["new_crease_length_L0_mean"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(c2["stages"][1]["new_crease_length_L0_sem"].get<double>(), expected({1.0, 2.0}).sem);
  EXPECT_DOUBLE_EQ(c2["share_after_compress_mean"].get<double>(), expected({0.1, 0.3}).mean);
  EXPECT_DOUBLE_EQ(c2["share_after_compress_max"].get<double>(), 0.3);

  const J& ts = e["threshold_sensitivity"];
  EXPECT_EQ(ts["key_kind"], "factor");
  EXPECT_EQ(ts["used_factor"].get<double>(), 0.5);
  ASSERT_EQ(ts["cycles"].size(), 1u);
  EXPECT_DOUBLE_EQ(ts["cycles"][0]["crease_length_L0_mean"][0].get<double>(), 4.5);
  EXPECT_DOUBLE_EQ(ts["cycles"][0]["perimeter_P_sem"][1].get<double>(), expected({1.0, 2.0}).sem);
  EXPECT_DOUBLE_EQ(ts["thresholds_mean"][1].get<double>(), 0.3);

  // Without per-stage data in one run: the statistics use the others, and say so.
  std::vector<J> mixed = docs;
  for (auto& c : mixed[1]["cycles"]) c["stages"] = J::array();
  const J m = ensemble_json(as_runs(mixed));
  EXPECT_EQ(m["stages"]["n_runs_with_stages"], 1);
  EXPECT_NE(m["stages"]["note"].get<std::string>().find("1 of 2 runs"), std::string::npos);
}

namespace {

int run_analyze(const std::string& args) {
  const std::string cmd = std::string(CRUMPLE_ANALYZE_EXE) + " " + args + " > /dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

// crumple-analyze ensemble on the output folders of two analysed synthetic runs.
TEST(Ensemble, CommandLine) {
  const fs::path dir = fs::temp_directory_path() / "crumple_test_ensemble_cli";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const MeshData m = synth::square_grid_mesh(20, 0.1);
  for (int s = 1; s <= 2; ++s) {
    std::vector<std::vector<double>> cycles;
    std::vector<double> p(m.hinges.size(), 0.0);
    for (int n = 1; n <= 3; ++n) {
      for (auto h : synth::hinges_on_line(m, (n + s) % 2, 0.01 * (2 * n + s))) p[h] = 0.9;
      cycles.push_back(p);
    }
    synth::WriteOptions o;
    o.cycle_compaction.assign(3, 0.27);
    const fs::path run = dir / ("seed" + std::to_string(s) + ".h5");
    synth::write_run(run.string(), m, cycles, o);
    ASSERT_EQ(run_analyze(run.string() + " --bootstrap 20"), 0);
  }
  const fs::path out = dir / "results" / "ensemble.json";
  const std::string analyses = (dir / "seed1.analysis").string() + " " +
                               (dir / "seed2.analysis" / "stats.json").string();
  ASSERT_EQ(run_analyze("ensemble -o " + out.string() + " " + analyses), 0);
  std::ifstream in(out);
  const J e = J::parse(in);
  EXPECT_EQ(e["n_runs"], 2);
  EXPECT_EQ(e["cycles"].size(), 3u);
  EXPECT_EQ(e["compaction"].get<double>(), 0.27);
  EXPECT_EQ(e["runs"][1]["analysis_dir"].get<std::string>(),
            fs::absolute(dir / "seed2.analysis").lexically_normal().string());
  EXPECT_TRUE(e["fits"]["perimeter_P"]["increments"].contains("C"));
  // Bad input: exit 2 and nothing written.
  const fs::path bad = dir / "bad.json";
  EXPECT_EQ(run_analyze("ensemble -o " + bad.string() + " " + (dir / "nope").string()), 2);
  std::ofstream(dir / "broken.json") << "{ not json";
  EXPECT_EQ(run_analyze("ensemble -o " + bad.string() + " " + (dir / "broken.json").string()), 2);
  EXPECT_EQ(run_analyze("ensemble " + analyses), 2) << "no -o";
  EXPECT_EQ(run_analyze("--threshold 0.1 ensemble -o " + bad.string() + " " + analyses), 2)
      << "a per-run option";
  EXPECT_FALSE(fs::exists(bad));
  EXPECT_EQ(run_analyze(""), 2) << "neither a run file nor ensemble";
  fs::remove_all(dir);
}

// The collapse over ensembles of several compaction ratios: seeds scattered about the
// experiments' law l = c1 (1 - D) ln(1 + c2 n/D) with offsets that cancel in every cycle give
// back (c1, c2) from the global fit; each ratio keeps its own fit; the collapsed points are
// n/D against mean/(1 - D); an ensemble without one compaction is refused by name.
TEST(Collapse, GlobalFitOverEnsemblesRecoversTheLaw) {
  const double c1 = 52, c2 = 0.1;
  const std::vector<double> ratios = {0.45, 0.27, 0.09};
  const std::vector<double> offset = {0.3, -0.1, -0.2};
  const fs::path dir = fs::temp_directory_path() / "crumple_test_collapse";
  fs::remove_all(dir);
  std::vector<EnsembleInput> inputs;
  for (double D : ratios) {
    std::vector<J> docs;
    for (int s = 0; s < 3; ++s) {
      std::vector<double> P, l;
      for (int n = 1; n <= 5; ++n) {
        const double y = c1 * (1 - D) * std::log1p(c2 * n / D);
        P.push_back(y + offset[s] * n), l.push_back(2 * y + offset[(s + 1) % 3] * n);
      }
      docs.push_back(stats_doc(s + 1, P, l, D));
    }
    // (not "D" + std::to_string(D): GCC 12 warns falsely on operator+(const char*, string&&))
    const fs::path path = dir / (std::string("D").append(std::to_string(D)).append(".json"));
    write_ensemble(path.string(), ensemble_json(as_runs(docs)));
    inputs.push_back(read_ensemble(path.string()));
  }
  const J c = collapse_json(inputs);
  EXPECT_EQ(c["compactions"].size(), 3u);
  EXPECT_TRUE(c["notes"].empty()) << c["notes"].dump();
  for (const char* q : {"perimeter_P", "crease_length_L0"}) {
    const double scale = std::string(q) == "perimeter_P" ? 1.0 : 2.0;
    const J& f = c["fits"][q]["increments"];
    SCOPED_TRACE(q);
    ASSERT_FALSE(f.contains("error")) << f.dump();
    EXPECT_TRUE(f["weighted"].get<bool>());
    EXPECT_NEAR(f["c1"].get<double>(), scale * c1, 1e-6 * c1);
    EXPECT_NEAR(f["c2"].get<double>(), c2, 1e-6 * c2);
    EXPECT_EQ(f["points"], 15);
    EXPECT_NEAR(f["chi2"].get<double>(), 0.0, 1e-10);
    EXPECT_NEAR(c["fits"][q]["cumulative"]["c2"].get<double>(), c2, 1e-6 * c2);
    ASSERT_EQ(c["points"][q].size(), 15u);
    const J& p = c["points"][q][7];  // D = 0.27, cycle 3
    EXPECT_DOUBLE_EQ(p["x"].get<double>(), 3 / 0.27);
    EXPECT_NEAR(p["y"].get<double>(), scale * c1 * std::log1p(c2 * 3 / 0.27), 1e-9);
  }
  ASSERT_EQ(c["groups"].size(), 3u);
  EXPECT_EQ(c["groups"][1]["compaction"].get<double>(), 0.27);
  EXPECT_NEAR(c["groups"][1]["fits"]["perimeter_P"]["c2"].get<double>(), c2, 1e-6);

  // One ratio only: said, and the fit is that ratio's.
  const J one = collapse_json({inputs[1]});
  ASSERT_EQ(one["notes"].size(), 1u);
  EXPECT_NEAR(one["fits"]["perimeter_P"]["increments"]["c1"].get<double>(), c1, 1e-6 * c1);

  // Refused: an ensemble of mixed compactions, a missing file, broken JSON.
  std::vector<J> mixed = {stats_doc(1, {1, 2, 3}, {1, 2, 3}, 0.27),
                          stats_doc(2, {1, 2, 3}, {1, 2, 3}, 0.45)};
  const fs::path bad = dir / "mixed.json";
  write_ensemble(bad.string(), ensemble_json(as_runs(mixed)));
  try {
    read_ensemble(bad.string());
    FAIL() << "an ensemble without one compaction must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(bad.string() + ": no single compaction ratio"),
              std::string::npos) << e.what();
  }
  EXPECT_THROW(read_ensemble((dir / "nope.json").string()), InputError);
  std::ofstream(dir / "broken.json") << "{ not json";
  EXPECT_THROW(read_ensemble((dir / "broken.json").string()), InputError);

  // The command line: exit 0 and the document; bad input exit 2 and nothing written.
  const fs::path out = dir / "collapse.json";
  std::string args;
  for (const auto& in : inputs) args += " " + in.path;
  ASSERT_EQ(run_analyze("collapse -o " + out.string() + args), 0);
  EXPECT_TRUE(fs::exists(out));
  const fs::path none = dir / "none.json";
  EXPECT_EQ(run_analyze("collapse -o " + none.string() + " " + bad.string()), 2);
  EXPECT_EQ(run_analyze("--threshold 0.1 collapse -o " + none.string() + args), 2);
  EXPECT_FALSE(fs::exists(none));
  fs::remove_all(dir);
}
