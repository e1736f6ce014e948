// The crease threshold: derived from the run's yield curvature c0 in /config (default factor,
// other factors, the default c0 when the config has none, an absolute override, c0 = 0
// refused), and the threshold sensitivity table (thresholds F c0, l non-increasing in the
// threshold, the default factor's row equal to the main result).
#include "analysis/creases/threshold_rule.hpp"
#include "analysis/io/run_reader.hpp"
#include "analysis/run/analyze_run.hpp"
#include "analysis/run/config_params.hpp"
#include "sim/model/crease_rule.hpp"
#include "tests/analysis/synthetic_run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace crumple::analysis;

namespace {

/// One or more cycles of a random plastic field whose |p| spreads over 0 .. 1.
RunData random_run(const std::string& config, int cycles = 1) {
  RunData run;
  run.path = "memory";
  run.mesh = synth::square_grid_mesh(16, 0.1);
  run.config_yaml = config;
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> p(run.mesh.hinges.size(), 0.0);
  for (int c = 1; c <= cycles; ++c) {
    for (auto& v : p)
      if (std::abs(v) < 0.05) v = u(rng) * u(rng) * u(rng);  // mostly small, some large
    run.cycles.push_back({c, p});
  }
  return run;
}

AnalyzeOptions cheap() {
  AnalyzeOptions o;
  o.bootstrap = 10;
  return o;
}

bool has_warning(const RunAnalysis& r, const std::string& needle) {
  for (const auto& w : r.warnings)
    if (w.find(needle) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(ThresholdRule, FractionOfC0FromTheConfig) {
  EXPECT_EQ(plastic_c0_from_config("integrator:\n  plastic_c0: 0.3\n"), 0.3);
  EXPECT_FALSE(plastic_c0_from_config("mesh: {size: 1}\n").has_value());
  EXPECT_FALSE(plastic_c0_from_config("").has_value());
  EXPECT_FALSE(plastic_c0_from_config("{not yaml").has_value());

  const RunAnalysis def = analyze_run(random_run("integrator:\n  plastic_c0: 0.3\n"), cheap());
  EXPECT_EQ(def.threshold_rule.kind, ThresholdRule::Kind::FractionOfC0);
  EXPECT_DOUBLE_EQ(def.threshold_rule.factor, kDefaultThresholdFactor);
  EXPECT_DOUBLE_EQ(def.threshold_rule.c0, 0.3);
  EXPECT_TRUE(def.threshold_rule.c0_from_config);
  EXPECT_DOUBLE_EQ(def.threshold_rule.threshold, kDefaultThresholdFactor * 0.3);
  EXPECT_NE(def.threshold_rule.note.find("c0"), std::string::npos);
  EXPECT_FALSE(has_warning(def, "plastic_c0"));

  AnalyzeOptions o = cheap();
  o.threshold_c0 = 1.5;
  const RunAnalysis f = analyze_run(random_run("integrator: {plastic_c0: 0.2}\n"), o);
  EXPECT_DOUBLE_EQ(f.threshold_rule.threshold, 0.3);
  EXPECT_LT(f.cycles[0].crease_length_L0, def.cycles[0].crease_length_L0);  // 0.3 > 0.15
}

TEST(ThresholdRule, DefaultC0AbsoluteOverrideAndZeroC0) {
  const RunAnalysis none = analyze_run(random_run("mesh: {size: 0.1}\n"), cheap());
  EXPECT_DOUBLE_EQ(none.threshold_rule.c0, kDefaultPlasticC0);
  EXPECT_FALSE(none.threshold_rule.c0_from_config);
  EXPECT_DOUBLE_EQ(none.threshold_rule.threshold, kDefaultThresholdFactor * kDefaultPlasticC0);
  EXPECT_TRUE(has_warning(none, "plastic_c0"));

  AnalyzeOptions o = cheap();
  o.threshold = 0.07;
  const RunAnalysis abs = analyze_run(random_run("integrator: {plastic_c0: 0.35}\n"), o);
  EXPECT_EQ(abs.threshold_rule.kind, ThresholdRule::Kind::Absolute);
  EXPECT_DOUBLE_EQ(abs.threshold_rule.threshold, 0.07);
  EXPECT_DOUBLE_EQ(abs.threshold_rule.factor, 0.2);  // 0.07 = 0.2 c0, said in the note
  EXPECT_NE(abs.threshold_rule.note.find("--threshold"), std::string::npos);

  // c0 = 0: a fraction of it is no threshold (every plastic hinge would count).
  EXPECT_THROW(analyze_run(random_run("integrator: {plastic_c0: 0}\n"), cheap()), InputError);
  // An absolute threshold (o still has 0.07) works, without a sensitivity table.
  const RunAnalysis zero = analyze_run(random_run("integrator: {plastic_c0: 0}\n"), o);
  EXPECT_TRUE(zero.sensitivity.factors.empty());
  EXPECT_THROW(threshold_from_c0(0.0, 0.3, true), std::invalid_argument);
  EXPECT_THROW(absolute_threshold(-1.0, 0.3, true), std::invalid_argument);
}

TEST(ThresholdSensitivity, MonotoneAndConsistentWithTheMainResult) {
  const RunAnalysis r = analyze_run(random_run("integrator: {plastic_c0: 0.3}\n", 3), cheap());
  const auto& s = r.sensitivity;
  ASSERT_EQ(s.factors.size(), kSensitivityFactors.size());
  ASSERT_EQ(s.cycles.size(), 3u);
  std::size_t default_row = s.factors.size();
  for (std::size_t k = 0; k < s.factors.size(); ++k) {
    EXPECT_DOUBLE_EQ(s.factors[k], kSensitivityFactors[k]);
    EXPECT_DOUBLE_EQ(s.thresholds[k], kSensitivityFactors[k] * 0.3);
    if (s.factors[k] == kDefaultThresholdFactor) default_row = k;
  }
  ASSERT_LT(default_row, s.factors.size()) << "the default factor should be in the table";
  for (std::size_t c = 0; c < s.cycles.size(); ++c) {
    const auto& row = s.cycles[c];
    EXPECT_EQ(row.cycle, static_cast<int>(c) + 1);
    ASSERT_EQ(row.crease_length_L0.size(), s.factors.size());
    for (std::size_t k = 1; k < s.factors.size(); ++k)
      EXPECT_LE(row.crease_length_L0[k], row.crease_length_L0[k - 1]) << c << " " << k;
    EXPECT_GT(row.crease_length_L0.front(), row.crease_length_L0.back());  // it does matter
    EXPECT_DOUBLE_EQ(row.crease_length_L0[default_row], r.cycles[c].crease_length_L0);
    EXPECT_DOUBLE_EQ(row.perimeter_P[default_row], r.cycles[c].perimeter_P);
    EXPECT_EQ(row.n_facets[default_row], static_cast<long>(r.cycles[c].facets.size()));
  }
}

// The run file's crease masks, which ParaView shows (sim/model/crease_rule.hpp), use the
// analysis's default threshold: the two programs share no code, so this holds them together.
TEST(Threshold, RunFileMasksUseTheAnalysisDefault) {
  EXPECT_EQ(crumple::kCreaseThresholdFactor, crumple::analysis::kDefaultThresholdFactor);
}

// A run whose /config states output.crease_angle is analysed at that fold angle by default, on
// every mesh alike; an explicit --threshold-c0 or --threshold still overrides it; the run file's
// masks follow the same rule (crumple::crease_threshold).
TEST(ThresholdRule, TheRunsCreaseAngleIsTheDefault) {
  const std::string cfg = "integrator: {plastic_c0: 0.45}\noutput: {crease_angle: 18.3}\n";
  EXPECT_EQ(crease_angle_from_config(cfg), 18.3);
  EXPECT_FALSE(crease_angle_from_config("output: {crease_angle: 0}\n").has_value());
  EXPECT_FALSE(crease_angle_from_config("output: {dt: 0.01}\n").has_value());
  EXPECT_FALSE(crease_angle_from_config("{not yaml").has_value());

  const double expected = 2 * std::sin(18.3 * std::numbers::pi / 360);
  const RunAnalysis r = analyze_run(random_run(cfg), cheap());
  EXPECT_EQ(r.threshold_rule.kind, ThresholdRule::Kind::CreaseAngle);
  EXPECT_TRUE(r.threshold_rule.angle_from_config);
  EXPECT_DOUBLE_EQ(r.threshold_rule.angle_deg, 18.3);
  EXPECT_NEAR(r.threshold_rule.threshold, expected, 1e-15);
  EXPECT_NEAR(r.threshold_rule.factor, expected / 0.45, 1e-15);
  EXPECT_NE(r.threshold_rule.note.find("output.crease_angle"), std::string::npos);
  EXPECT_NEAR(crumple::crease_threshold(0.45, 18.3), expected, 1e-15);
  EXPECT_DOUBLE_EQ(crumple::crease_threshold(0.45, 0.0), crumple::kCreaseThresholdFactor * 0.45);

  AnalyzeOptions by_c0 = cheap();
  by_c0.threshold_c0 = 0.5;
  by_c0.threshold_c0_given = true;
  EXPECT_DOUBLE_EQ(analyze_run(random_run(cfg), by_c0).threshold_rule.threshold, 0.225);
  AnalyzeOptions absolute = cheap();
  absolute.threshold = 0.1;
  EXPECT_DOUBLE_EQ(analyze_run(random_run(cfg), absolute).threshold_rule.threshold, 0.1);
  AnalyzeOptions by_angle = cheap();
  by_angle.crease_angle = 30.0;  // --crease-angle: the same rule for a run made without the key
  const RunAnalysis a = analyze_run(random_run("integrator: {plastic_c0: 0.45}\n"), by_angle);
  EXPECT_NEAR(a.threshold_rule.threshold, 2 * std::sin(15 * std::numbers::pi / 180), 1e-15);
  EXPECT_NE(a.threshold_rule.note.find("--crease-angle"), std::string::npos);
  EXPECT_FALSE(a.threshold_rule.angle_from_config);
  EXPECT_THROW(threshold_from_crease_angle(180.0, 0.3, true, true), std::invalid_argument);
}
