// Configuration: every class of bad input names file:line:column and the key; defaults and
// the resolved YAML round trip; the units mapping of eq. 5-7.
#include "sim/core/errors.hpp"
#include "sim/io/config.hpp"
#include "sim/io/units.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace crumple;

namespace {
std::string error_of(const std::string& yaml, const std::vector<std::string>& sets = {}) {
  try {
    load_config_text(yaml, "c.yaml", sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
bool starts(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
}  // namespace

TEST(Config, UnknownKeyListsTheValidOnes) {
  const std::string e = error_of("mesh:\n  nodez: 10\n");
  EXPECT_TRUE(starts(e, "c.yaml:2:3: mesh.nodez: unknown key (valid: shape, nodes")) << e;
  EXPECT_TRUE(starts(error_of("meshes: {}\n"), "c.yaml:1:1: meshes: unknown section")) << error_of("meshes: {}\n");
}

TEST(Config, WrongType) {
  const std::string e = error_of("mesh:\n  nodes: many\n");
  EXPECT_TRUE(starts(e, "c.yaml:2:10: mesh.nodes: expected a whole number, got 'many'")) << e;
  EXPECT_TRUE(starts(error_of("output:\n  xdmf: perhaps\n"), "c.yaml:2:9: output.xdmf: expected true or false"));
}

TEST(Config, OutOfRange) {
  const std::string e = error_of("material:\n  thickness: -3\n");
  EXPECT_TRUE(starts(e, "c.yaml:2:14: material.thickness: must be > 0, got -3")) << e;
  EXPECT_TRUE(starts(error_of("integrator:\n  bdf_order: 5\n"), "c.yaml:2:14: integrator.bdf_order: must be between 1 and 4"));
}

TEST(Config, UnknownChoiceListsTheValidOnes) {
  const std::string e = error_of("integrator:\n  linear_solver: magic\n");
  EXPECT_TRUE(starts(e, "c.yaml:2:18: integrator.linear_solver: unknown value 'magic'")) << e;
  EXPECT_NE(e.find("block_jacobi"), std::string::npos);
}

TEST(Config, SyntaxError) {
  const std::string e = error_of("mesh:\n  nodes: [1, 2\n");
  EXPECT_TRUE(starts(e, "c.yaml:")) << e;
  EXPECT_NE(e.find("YAML syntax error"), std::string::npos) << e;
}

TEST(Config, MissingFile) {
  try {
    load_config("no/such/file.yaml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(starts(e.what(), "no/such/file.yaml: cannot open")) << e.what();
  }
}

TEST(Config, OverridesAndTheirErrors) {
  const Params p = load_config_text("mesh:\n  nodes: 500\n", "c.yaml", {"mesh.nodes=800", "protocol.cycles=3"});
  EXPECT_EQ(p.mesh.nodes, 800);
  EXPECT_EQ(p.protocol.cycles, 3);
  EXPECT_TRUE(starts(error_of("", {"mesh.nodes=-5"}), "--set mesh.nodes=-5: mesh.nodes: must be between"))
      << error_of("", {"mesh.nodes=-5"});
  EXPECT_TRUE(starts(error_of("", {"mesh.nodez=5"}), "--set mesh.nodez=5: mesh.nodez: unknown key"));
  EXPECT_TRUE(starts(error_of("", {"nodes"}), "--set nodes: expected dotted.key=value"));
}

TEST(Config, DirectConstantsComeTogether) {
  const std::string e = error_of("material:\n  ks: 1\n  kb: 2\n");
  EXPECT_NE(e.find("material.mass: ks, kb and mass are given together"), std::string::npos) << e;
}

TEST(Config, CgToleranceBoundsAreOrdered) {
  const std::string e = error_of("integrator:\n  cg_tol_max: 0.01\n  cg_tol: 0.05\n");
  EXPECT_TRUE(starts(e, "c.yaml:3:11: integrator.cg_tol: need integrator.cg_tol <= "
                        "integrator.cg_tol_max, got 0.05 > 0.01")) << e;
  const Params p = load_config_text("integrator: {cg_tol: 1e-3, cg_tol_max: 1e-3}\n", "c.yaml");
  EXPECT_EQ(p.integrator.cg_tol_max, 1e-3);  // equal bounds: a fixed tolerance
  // Only cg_tol_max set, below the default cg_tol: its own line is named.
  const std::string m = error_of("integrator:\n  cg_tol_max: 0.001\n");
  EXPECT_TRUE(starts(m, "c.yaml:2:15: integrator.cg_tol_max: need integrator.cg_tol <=")) << m;
}

// Every relation and open bound that the integrator would otherwise reject later, without a
// line, is caught where the file sets it.
TEST(Config, IntegratorRelationsAndOpenBoundsNameTheLine) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"integrator:\n  cg_tol: 1\n", "c.yaml:2:11: integrator.cg_tol: must be > 0 and < 1"},
      {"integrator:\n  cg_tol_max: 1\n",
       "c.yaml:2:15: integrator.cg_tol_max: must be > 0 and < 1"},
      {"integrator:\n  plastic_c0: 2\n",
       "c.yaml:2:15: integrator.plastic_c0: must be >= 0 and < 2"},
      {"integrator:\n  h_min: 1\n  h_max: 0.5\n",
       "c.yaml:2:10: integrator.h_min: need integrator.h_min <= integrator.h_max"},
      {"integrator:\n  h_min: 1e-6\n  h_init: 1e-7\n",
       "c.yaml:3:11: integrator.h_init: need integrator.h_min <="},
      {"integrator:\n  h_init: 1e-13\n", "c.yaml:2:11: integrator.h_init: must be >= 1e-12"},
      {"integrator:\n  h_max: 1e-5\n", "c.yaml:2:10: integrator.h_max: need integrator.h_init <="},
      {"integrator:\n  h_init: 0.5\n", "c.yaml:2:11: integrator.h_init: need integrator.h_init <="},
      {"integrator:\n  switch_up: 1e-3\n  switch_down: 1e-3\n",
       "c.yaml:3:16: integrator.switch_down: need integrator.switch_down < integrator.switch_up"},
      {"integrator:\n  switch_up: 1e-7\n",
       "c.yaml:2:14: integrator.switch_up: need integrator.switch_down < integrator.switch_up"},
  };
  for (const auto& [yaml, want] : cases) {
    const std::string e = error_of(yaml);
    EXPECT_TRUE(starts(e, want)) << yaml << " -> " << e;
  }
  EXPECT_TRUE(starts(error_of("", {"integrator.h_init=0.5"}),
                     "--set integrator.h_init=0.5: integrator.h_init: need"))
      << error_of("", {"integrator.h_init=0.5"});
  // The file sets one key of the pair, --set the other that breaks the relation: the --set.
  const std::string both = error_of("integrator:\n  h_init: 1e-4\n", {"integrator.h_max=1e-5"});
  EXPECT_TRUE(starts(both, "--set integrator.h_max=1e-5: integrator.h_max: need integrator.h_init "
                           "<= integrator.h_max, got 0.0001 > 1e-05")) << both;
  // Values close together are printed with enough digits to differ.
  const std::string close = error_of("integrator:\n  h_init: 1.0000001e-4\n  h_max: 1e-4\n");
  EXPECT_NE(close.find("got 0.00010000001 > 0.0001"), std::string::npos) << close;
  // The closed ends stay allowed.
  const Params p = load_config_text("integrator: {plastic_c0: 1.99, h_min: 1e-4, h_init: 1e-4}\n",
                                    "c.yaml");
  EXPECT_EQ(p.integrator.plastic_c0, 1.99);
}

TEST(Config, TwoLevelSolverAndItsPatchSize) {
  const Params p = load_config_text("integrator: {linear_solver: two_level, coarse_nodes: 48}\n", "c.yaml");
  EXPECT_EQ(p.integrator.linear_solver, LinearSolverKind::TwoLevelCG);
  EXPECT_EQ(p.integrator.coarse_nodes, 48);
  const std::string e = error_of("integrator:\n  coarse_nodes: 2\n");
  EXPECT_TRUE(starts(e, "c.yaml:2:17: integrator.coarse_nodes: must be between 3")) << e;
}

TEST(Config, ResolvedYamlRoundTrips) {
  const Params p = load_config_text(
      "mesh: {shape: disk, nodes: 777, size: 0.3}\n"
      "integrator: {rtol: 3.3e-5, linear_solver: two_level, coarse_nodes: 40}\n"
      "protocol:\n  cycles: 2\n  stages:\n    - {type: roll, duration: 0.1}\n",
      "c.yaml");
  const std::string y1 = resolved_yaml(p);
  const Params q = load_config_text(y1, "resolved");
  EXPECT_EQ(resolved_yaml(q), y1);
  EXPECT_EQ(q.mesh.nodes, 777);
  EXPECT_EQ(q.integrator.rtol, 3.3e-5);
  EXPECT_EQ(q.integrator.linear_solver, LinearSolverKind::TwoLevelCG);
  EXPECT_EQ(q.integrator.coarse_nodes, 40);
  EXPECT_EQ(q.protocol.stages[0]["duration"].as<double>(), 0.1);
}

TEST(Units, PhysicalMaterialMapsToTheModel) {
  MaterialParams m;
  m.thickness = 2.5e-4;
  m.young_modulus = 1e9;
  m.density = 1400;
  m.mass_scale = 1;
  const ResolvedMaterial r = resolve_material(m, 0.01, 1000);
  EXPECT_NEAR(r.h_eff, 2.5e-4, 1e-15);                                   // eq. 7
  EXPECT_NEAR(r.y2d, 1e9 * 2.5e-4, 1e-6);                                // Y = Y2D / h
  EXPECT_NEAR(r.kappa, 1e9 * std::pow(2.5e-4, 3) / (12 * (1 - 1.0 / 9)), 1e-15);  // eq. 5
  EXPECT_NEAR(r.model.mass, 1400 * 2.5e-4 * 0.01 / 1000, 1e-20);
  EXPECT_NEAR(r.model.b_iso, 0.01 * std::sqrt(r.model.ks * r.model.mass), 1e-18);
}

// yaml-cpp would keep the first of two equal keys and accept a list as a key: both are errors
// with the places of both keys, at any depth (a stage's parameters too).
TEST(Config, DuplicateAndComplexKeysAreRefused) {
  EXPECT_EQ(error_of("mesh:\n  nodes: 100\n  nodes: 200\n"),
            "c.yaml:3:3: mesh.nodes: duplicate key (first at c.yaml:2:3)");
  EXPECT_EQ(error_of("mesh: {}\nmesh: {}\n"), "c.yaml:2:1: mesh: duplicate key (first at c.yaml:1:1)");
  EXPECT_TRUE(starts(error_of("protocol:\n  stages:\n    - {type: roll, duration: 1, duration: 2}\n"),
                     "c.yaml:3:33: protocol.stages[0].duration: duplicate key (first at c.yaml:3:20)"))
      << error_of("protocol:\n  stages:\n    - {type: roll, duration: 1, duration: 2}\n");
  EXPECT_TRUE(starts(error_of("? [a, b]\n: 1\n"), "c.yaml:1:3: a key must be a plain word"))
      << error_of("? [a, b]\n: 1\n");
}

// A --set error names the argument, whatever part of it is wrong; an empty value is refused
// (YAML would read it as null, i.e. "the default").
TEST(Config, SetErrorsNameTheArgument) {
  EXPECT_EQ(error_of("", {"mesh.nodes="}), "--set mesh.nodes=: empty value (give mesh.nodes=VALUE)");
  EXPECT_TRUE(starts(error_of("", {"foo.bar=1"}), "--set foo.bar=1: foo: unknown section"))
      << error_of("", {"foo.bar=1"});
  EXPECT_TRUE(starts(error_of("", {"mesh.nodez=1"}), "--set mesh.nodez=1: mesh.nodez: unknown key"))
      << error_of("", {"mesh.nodez=1"});
  const Params p = load_config_text("mesh: {nodes: 200}\n", "c.yaml", {"protocol.stages=[{type: roll}]"});
  EXPECT_EQ(p.protocol.stages_source, "--set protocol.stages=[{type: roll}]");
  EXPECT_EQ(p.where("mesh.nodes"), "c.yaml:1:15: mesh.nodes");
  EXPECT_EQ(p.where("output.dt"), "c.yaml: output.dt (default)");
}

// One stage parameter set from the command line, by stage type or by index; the place is the
// --set argument (ProtocolParams::stage_sets), the rest of the list keeps the file's places.
TEST(Config, StageParametersBySet) {
  const std::string two =
      "protocol:\n  stages:\n    - {type: roll, duration: 0.2}\n"
      "    - {type: compress, compaction: 0.27}\n    - {type: release}\n";
  const Params p = load_config_text(two, "c.yaml", {"protocol.stages.compress.compaction=0.18",
                                                    "protocol.stages.0.duration=0.3"});
  EXPECT_DOUBLE_EQ(p.protocol.stages[1]["compaction"].as<double>(), 0.18);
  EXPECT_DOUBLE_EQ(p.protocol.stages[0]["duration"].as<double>(), 0.3);
  EXPECT_EQ(p.protocol.stages_source, "c.yaml");
  EXPECT_EQ(p.protocol.stage_sets.at("protocol.stages[1].compaction"),
            "--set protocol.stages.compress.compaction=0.18");
  EXPECT_EQ(p.protocol.stage_sets.at("protocol.stages[0].duration"),
            "--set protocol.stages.0.duration=0.3");
  // A new key of a stage is added (the registry validates it later).
  const Params q = load_config_text(two, "c.yaml", {"protocol.stages.release.min_duration=0.1"});
  EXPECT_DOUBLE_EQ(q.protocol.stages[2]["min_duration"].as<double>(), 0.1);

  const std::string twice = two + "    - {type: compress, compaction: 0.1}\n";
  EXPECT_EQ(error_of(twice, {"protocol.stages.compress.compaction=0.2"}),
            "--set protocol.stages.compress.compaction=0.2: the protocol has 2 compress stages "
            "(1, 3): name one by its index, e.g. protocol.stages.1.compaction=...");
  const Params r = load_config_text(twice, "c.yaml", {"protocol.stages.3.compaction=0.2"});
  EXPECT_DOUBLE_EQ(r.protocol.stages[3]["compaction"].as<double>(), 0.2);
  EXPECT_DOUBLE_EQ(r.protocol.stages[1]["compaction"].as<double>(), 0.27);
  EXPECT_EQ(error_of(two, {"protocol.stages.fold.angle=1"}),
            "--set protocol.stages.fold.angle=1: no stage of type 'fold' in the protocol (the "
            "stages are 0: roll, 1: compress, 2: release)");
  EXPECT_TRUE(starts(error_of(two, {"protocol.stages.9.speed=1"}),
                     "--set protocol.stages.9.speed=1: stage index 9 out of range"));
  EXPECT_TRUE(starts(error_of(two, {"protocol.stages.compress=1"}),
                     "--set protocol.stages.compress=1: a stage parameter is"));
  EXPECT_TRUE(starts(error_of(two, {"protocol.stages.compress.type=roll"}),
                     "--set protocol.stages.compress.type=roll: a stage's type cannot be set"));
  EXPECT_TRUE(starts(error_of("", {"protocol.stages.compress.speed=1"}),
                     "--set protocol.stages.compress.speed=1: the protocol has no stage list"));
  // A whole new list drops the stage sets made before it.
  const Params s = load_config_text(two, "c.yaml", {"protocol.stages.compress.compaction=0.18",
                                                    "protocol.stages=[{type: roll}]"});
  EXPECT_TRUE(s.protocol.stage_sets.empty());
}

TEST(Config, YieldRadiusAndPlasticC0AreNotBothGiven) {
  // The yield radius sets c0 on each mesh: giving both is refused, naming both places.
  const std::string e = error_of("material: {yield_radius: 0.005}\nintegrator: {plastic_c0: 0.3}\n");
  EXPECT_TRUE(starts(e, "c.yaml:2:26: integrator.plastic_c0: given together with material.yield_radius"))
      << e;
  EXPECT_NE(e.find("material.yield_radius (c.yaml:1:26), which sets it"), std::string::npos) << e;
  const std::string by_set = error_of("integrator: {plastic_c0: 0.3}\n", {"material.yield_radius=0.005"});
  EXPECT_NE(by_set.find("--set material.yield_radius=0.005"), std::string::npos) << by_set;
  EXPECT_NE(error_of("material: {yield_radius: -0.001}\n").find("material.yield_radius: must be >= 0"),
            std::string::npos);
  // 0 unsets a protocol's radius: c0 is then given directly again.
  EXPECT_EQ(load_config_text("material: {yield_radius: 0.005}\nprotocol:\n  stages:\n"
                             "    - {type: roll, duration: 0.1}\n", "c.yaml", {"material.yield_radius=0",
                                                                              "integrator.plastic_c0=0.3"})
                .integrator.plastic_c0, 0.3);
  // Alone, it loads; the configuration printed before a mesh is known leaves c0 out and reads
  // back the same.
  const Params p = load_config_text(
      "material: {yield_radius: 0.005}\nprotocol:\n  stages:\n    - {type: roll, duration: 0.1}\n",
      "c.yaml");
  EXPECT_EQ(p.material.yield_radius, 0.005);
  const std::string y = resolved_yaml(p);
  EXPECT_EQ(y.find("plastic_c0"), std::string::npos) << y;
  EXPECT_EQ(resolved_yaml(load_config_text(y, "resolved")), y);
}

TEST(Config, YieldAngleIsOneOfTheThreeStatementsOfTheYield) {
  // The yield angle, the yield radius and c0 each fix the hinge yield: any two are refused at
  // the later key, naming the place of the other.
  const std::string with_c0 = error_of("material: {yield_angle: 20}\nintegrator: {plastic_c0: 0.3}\n");
  EXPECT_TRUE(starts(with_c0, "c.yaml:2:26: integrator.plastic_c0: given together with "
                              "material.yield_angle (c.yaml:1:25), which sets it on every mesh"))
      << with_c0;
  const std::string with_radius = error_of("material: {yield_radius: 0.005, yield_angle: 20}\n");
  EXPECT_TRUE(starts(with_radius, "c.yaml:1:46: material.yield_angle: given together with "
                                  "material.yield_radius (c.yaml:1:26): two statements"))
      << with_radius;
  EXPECT_NE(error_of("material: {yield_angle: 180}\n").find("material.yield_angle: must be >= 0 and < 180"),
            std::string::npos);
  // 0 unsets a file's angle, so a yield radius can replace it (the studies of the yield radius).
  const Params radius = load_config_text("material: {yield_angle: 37}\n", "c.yaml",
                                         {"material.yield_angle=0", "material.yield_radius=0.0081"});
  EXPECT_EQ(radius.material.yield_angle, 0);
  EXPECT_EQ(radius.material.yield_radius, 0.0081);
  // Alone it loads, and the configuration before a mesh leaves the derived c0 out.
  const Params p = load_config_text(
      "material: {yield_angle: 17.25}\nprotocol:\n  stages:\n    - {type: roll, duration: 0.1}\n",
      "c.yaml");
  EXPECT_EQ(p.material.yield_angle, 17.25);
  const std::string y = resolved_yaml(p);
  EXPECT_EQ(y.find("plastic_c0"), std::string::npos) << y;
  EXPECT_EQ(resolved_yaml(load_config_text(y, "resolved")), y);
  // Stored by a run with its derived c0, it reads back without the contradiction.
  Params run = p;
  run.integrator.plastic_c0 = 0.28125, run.c0_from_mesh = true;
  const Params back = load_stored_config(resolved_yaml(run), "run.h5:/config");
  EXPECT_EQ(back.material.yield_angle, 17.25);
  EXPECT_EQ(back.origins.count("integrator.plastic_c0"), 0u);
}

TEST(Config, StoredConfigWithAYieldRadiusKeepsItsDerivedC0ForReadersOnly) {
  // A run stores the c0 it derived beside the yield radius (for crumple-analyze); read back as
  // a configuration (to resume), the derived value is dropped, so the two do not contradict.
  Params p = load_config_text("material: {yield_radius: 0.005}\n", "c.yaml");
  p.integrator.plastic_c0 = 0.28125;  // exact in binary: printed as written
  p.c0_from_mesh = true;
  const std::string stored = resolved_yaml(p);
  EXPECT_NE(stored.find("plastic_c0: 0.28125"), std::string::npos) << stored;
  EXPECT_NE(error_of(stored), "");
  const Params back = load_stored_config(stored, "run.h5:/config");
  EXPECT_EQ(back.material.yield_radius, 0.005);
  EXPECT_EQ(back.integrator.plastic_c0, IntegratorSettings{}.plastic_c0);
  EXPECT_EQ(back.origins.count("integrator.plastic_c0"), 0u);
}
