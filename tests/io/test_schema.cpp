// The configuration schema (sim/io/config_schema.cpp, sim/integrate/settings_schema.cpp) is the
// only description of the keys: every key it declares is read, range-checked at both ends,
// printed by resolved_yaml and read back; every key resolved_yaml prints is declared; the
// defaults satisfy every rule; the integrator's own validate() applies the same table.
#include "sim/core/errors.hpp"
#include "sim/core/schema.hpp"
#include "sim/integrate/settings.hpp"
#include "sim/io/config.hpp"
#include "sim/io/config_schema.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <set>

using namespace crumple;
using schema::Kind;

namespace {

std::string error_of(const std::vector<std::string>& sets) {
  try {
    load_config_text("{}\n", "c.yaml", sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Values to try for a key other than its default: near it first (so that relations with the
/// other keys' defaults still hold), then the middle of the range.
std::vector<double> candidates(const schema::Key& k, double def) {
  std::vector<double> v;
  if (k.kind == Kind::Integer) {
    v = {def + 1, def - 1};
  } else {
    v = {def * 1.01, def * 0.99, def + 1};
  }
  const double lo = std::isfinite(k.lo) ? k.lo : def - 1;
  const double hi = std::isfinite(k.hi) ? k.hi : std::max(lo, def) * 2 + 1;
  v.push_back(k.kind == Kind::Integer ? std::floor(0.5 * (lo + hi)) : 0.5 * (lo + hi));
  std::vector<double> ok;
  for (double x : v)
    if (x != def && k.range_error(x, "").empty()) ok.push_back(x);
  return ok;
}

/// Just beyond a bound: the next whole number, or a relative step that the double resolves.
double beyond(double bound, double direction, bool whole) {
  if (whole && bound + direction != bound) return bound + direction;
  return bound + direction * (std::abs(bound) + 1) * 1e-3;
}

}  // namespace

TEST(Schema, DefaultsSatisfyEveryRule) {
  const Params p;
  for (const auto& cs : config_schema())
    EXPECT_EQ(schema::check(*cs.section, cs.of_const(p)), "") << cs.section->name;
}

TEST(Schema, EveryKeyIsReadPrintedAndReadBack) {
  const Params defaults;
  int keys = 0;
  for (const auto& cs : config_schema()) {
    for (const auto& k : cs.section->keys) {
      const std::string dotted = cs.section->name + "." + k.name;
      std::string text;
      if (k.kind == Kind::List) continue;
      // Keys of an all-or-none group (ks, kb, mass) are set together; the section's other keys
      // alone.
      const auto& group = cs.section->all_or_none;
      const bool grouped = std::find(group.begin(), group.end(), k.name) != group.end();
      if (k.kind == Kind::Word) {
        const std::string def = k.get_word(cs.of_const(defaults));
        text = k.choices.front() == def ? k.choices.back() : k.choices.front();
      } else if (k.kind == Kind::Flag) {
        text = k.get_number(cs.of_const(defaults)) != 0 ? "false" : "true";
      } else {
        // The first candidate the whole configuration accepts (relations included).
        for (double v : candidates(k, k.get_number(cs.of_const(defaults)))) {
          std::vector<std::string> sets{dotted + "=" + schema::format_number(v)};
          for (const auto& g : cs.section->all_or_none)
            if (grouped && g != k.name) sets.push_back(cs.section->name + "." + g + "=" + schema::format_number(v));
          if (error_of(sets).empty()) {
            text = schema::format_number(v);
            break;
          }
        }
        if (k.name == "poisson") continue;  // a single admissible value
        ASSERT_FALSE(text.empty()) << dotted << ": no other value accepted";
      }
      // ks, kb and mass come together.
      std::vector<std::string> sets{dotted + "=" + text};
      for (const auto& g : cs.section->all_or_none)
        if (grouped && g != k.name) sets.push_back(cs.section->name + "." + g + "=" + text);
      SCOPED_TRACE(sets.front());
      const Params p = load_config_text("{}\n", "c.yaml", sets);
      const std::string value = value_text(k, cs.of_const(p));
      EXPECT_EQ(value, k.kind == Kind::Real || k.kind == Kind::Integer
                           ? schema::format_number(std::stod(text))
                           : text);
      const Params back = load_config_text(resolved_yaml(p), "resolved.yaml");
      EXPECT_EQ(value_text(k, cs.of_const(back)), value);
      ++keys;
    }
  }
  EXPECT_GT(keys, 50);
}

TEST(Schema, RangesAreEnforcedAtBothEnds) {
  for (const auto& cs : config_schema()) {
    for (const auto& k : cs.section->keys) {
      if (k.kind != Kind::Real && k.kind != Kind::Integer) continue;
      const std::string dotted = cs.section->name + "." + k.name;
      SCOPED_TRACE(dotted);
      const bool whole = k.kind == Kind::Integer;
      // The range a config value must be in: the domain narrowed by the input bounds.
      const bool lo_input = k.input_lo > k.lo, hi_input = k.input_hi < k.hi;
      const double lo = lo_input ? k.input_lo : k.lo, hi = hi_input ? k.input_hi : k.hi;
      const bool lo_open = k.lo_open && !lo_input, hi_open = k.hi_open && !hi_input;
      if (std::isfinite(lo)) {
        const double below = lo_open && !whole ? lo : beyond(lo, -1, whole);
        const std::string e = error_of({dotted + "=" + schema::format_number(below)});
        EXPECT_NE(e.find(dotted + ": must be"), std::string::npos) << e;
      }
      if (std::isfinite(hi)) {
        const double above = hi_open && !whole ? hi : beyond(hi, 1, whole);
        const std::string e = error_of({dotted + "=" + schema::format_number(above)});
        EXPECT_NE(e.find(dotted + ": must be"), std::string::npos) << e;
      }
    }
  }
}

TEST(Schema, ResolvedYamlPrintsExactlyTheDeclaredKeys) {
  Params p;
  p.material.ks = 1, p.material.kb = 1, p.material.mass = 1;  // printed only when given
  p.material.yield_radius = 0.01;  // also printed only when given (with the yield angle:
  p.material.yield_angle = 20;     // together refused on input, but each is printed when set),
  p.output.crease_angle = 18.3;    // (a stated crease angle too)
  p.c0_from_mesh = true;           // and then plastic_c0 only once the run's mesh set it
  const YAML::Node root = YAML::Load(resolved_yaml(p));
  std::set<std::string> printed, declared;
  for (auto s = root.begin(); s != root.end(); ++s)
    for (auto k = s->second.begin(); k != s->second.end(); ++k)
      printed.insert(s->first.Scalar() + "." + k->first.Scalar());
  for (const auto& cs : config_schema())
    for (const auto& k : cs.section->keys) declared.insert(cs.section->name + "." + k.name);
  EXPECT_EQ(printed, declared);
}

TEST(Schema, RelationsNameTheKeyAndBothValues) {
  const std::string e = error_of({"integrator.cg_tol=0.5", "integrator.cg_tol_max=0.2"});
  EXPECT_EQ(e, "--set integrator.cg_tol=0.5: integrator.cg_tol: need integrator.cg_tol <= "
               "integrator.cg_tol_max, got 0.5 > 0.2");
}

TEST(Schema, IntegratorValidateAppliesTheSameTable) {
  IntegratorSettings s;
  EXPECT_NO_THROW(validate(s));
  s.block_size = 0;  // the domain is >= 1 (a config must give 3 to 600)
  try {
    validate(s);
    FAIL() << "block_size 0 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "integrator.block_size: must be >= 1, got 0");
  }
  s.block_size = 2;  // beyond the input bound, inside the domain: code may
  EXPECT_NO_THROW(validate(s));
  s.block_size = 18;
  s.h_min = 1e-16;
  EXPECT_NO_THROW(validate(s));
  EXPECT_NE(error_of({"integrator.h_min=1e-16"}).find("integrator.h_min: must be >= 1e-12"),
            std::string::npos);
  s = IntegratorSettings{};
  s.switch_down = s.switch_up;
  EXPECT_THROW(validate(s), InputError);
}

TEST(Schema, ResumableKeysAreTheDocumentedOnes) {
  const std::vector<std::string> keys = resumable_keys();
  const std::set<std::string> got(keys.begin(), keys.end());
  const std::set<std::string> want{
      "integrator.rtol",          "integrator.atol",          "integrator.h_init",
      "integrator.h_min",         "integrator.h_max",         "integrator.max_growth",
      "integrator.newton_tol",    "integrator.newton_max_iters", "integrator.newton_target",
      "integrator.cg_tol",        "integrator.cg_tol_max",    "integrator.cg_max_iters",
      "integrator.explicit_rtol", "output.dt",                "output.checkpoint_wall_s"};
  EXPECT_EQ(got, want);
}

TEST(Schema, DocsRangeNotation) {
  schema::Key k;
  k.kind = Kind::Real;
  EXPECT_EQ(k.above(0).range_doc(), "> 0");
  EXPECT_EQ(k.below(2).range_doc(), "(0, 2)");
  EXPECT_EQ(k.at_least(0).at_most(10).range_doc(), "[0, 10]");
  k.kind = Kind::Integer;
  EXPECT_EQ(k.in(10, 1e6).range_doc(), "10 to 1000000");
  EXPECT_EQ(schema::format_number(0.1), "0.1");
  EXPECT_EQ(schema::format_number(1.0 / 3.0), "0.3333333333333333");
}

// A key removed from the schema: a config that gives it is told why; a run file's stored
// configuration that holds it still loads (an older run can be resumed).
TEST(Schema, RetiredKeysAreExplainedAndDroppedFromStoredConfigs) {
  const std::string e = error_of({"output.crease_threshold=0.05"});
  EXPECT_NE(e.find("output.crease_threshold: retired"), std::string::npos) << e;
  Params p;
  p.protocol.stages = YAML::Load("[{type: roll}]");
  std::string stored = resolved_yaml(p);
  stored.replace(stored.find("output:\n"), 8, "output:\n  crease_threshold: 0.05\n");
  EXPECT_THROW(load_config_text(stored, "run.h5:/config"), InputError);
  const Params q = load_stored_config(stored, "run.h5:/config");
  EXPECT_EQ(resolved_yaml(q), resolved_yaml(p));
}
