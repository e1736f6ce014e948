// A run assembled from a config (sim/assemble/simulation.hpp): contact follows the config and the
// stages' switch, and a short protocol runs to its end through the assembled parts.
#include "sim/assemble/simulation.hpp"
#include "sim/io/config.hpp"
#include "sim/mesh/generate.hpp"

#include <gtest/gtest.h>

#include <map>

using namespace crumple;

namespace {

struct CountingSink : RunSink {
  const SheetModel* model = nullptr;
  int frames = 0, stage_ends = 0, cycles = 0;
  std::map<std::string, std::size_t> terms;  ///< stage -> the model's term count in its frames
  void frame(const State&, const std::string& stage, int) override {
    ++frames;
    if (model) terms[stage] = model->terms().size();
  }
  void stage_end(int, int, const Stage&, const State&) override { ++stage_ends; }
  void cycle_end(int, const State&) override { ++cycles; }
  void checkpoint(const Checkpoint&) override {}
};

const char* kConfig =
    "mesh: {nodes: 150, seed: 2}\n"
    "protocol:\n"
    "  cycles: 1\n"
    "  stages:\n"
    "    - {type: roll, duration: 0.05, max_duration: 0.2}\n"
    "    - {type: unfold, open_time: 0.05, max_duration: 0.2, contact: false}\n"
    "output: {dt: 0.05, checkpoint_wall_s: 0}\n";

}  // namespace

TEST(Run, ContactFollowsTheConfig) {
  const Params on = load_config_text(kConfig, "c.yaml");
  const Mesh mesh = generate_mesh(on.mesh);
  Simulation a(on, mesh, StageRegistry::builtin());
  ASSERT_NE(a.contact(), nullptr);
  EXPECT_EQ(a.contact_settings().ks, a.material().model.ks);
  const Params off = load_config_text(kConfig, "c.yaml", {"contact.enabled=false"});
  Simulation b(off, mesh, StageRegistry::builtin());
  EXPECT_EQ(b.contact(), nullptr);
  EXPECT_LT(b.model().terms().size(), a.model().terms().size());
}

TEST(Run, AShortProtocolRunsThroughTheAssembledParts) {
  const Params p = load_config_text(kConfig, "c.yaml");
  const Mesh mesh = generate_mesh(p.mesh);
  Simulation run(p, mesh, StageRegistry::builtin());
  State s = run.model().rest_state();
  CountingSink sink;
  sink.model = &run.model();
  EXPECT_TRUE(run.run(s, sink));
  EXPECT_EQ(sink.cycles, 1);
  EXPECT_EQ(sink.stage_ends, 2);
  EXPECT_GT(sink.frames, 0);
  EXPECT_GT(run.integrator().summary().steps(), 0);
  // The unfold stage asked for contact off: the assembled switch took its terms out.
  ASSERT_TRUE(sink.terms.count("roll") && sink.terms.count("unfold"));
  EXPECT_LT(sink.terms["unfold"], sink.terms["roll"]);
}
