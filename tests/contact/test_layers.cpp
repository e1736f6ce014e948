// Self-contact in a run: a sheet folded onto itself, its top half driven down onto the bottom
// half by the fold's tethers, never lets its layers pass through each other: the smallest
// distance between interacting contact sites stays >= 0.3 sigma at every step.
#include "sim/contact/self_contact.hpp"
#include "sim/mesh/generate.hpp"
#include "tests/protocols/runner_fixture.hpp"

#include <gtest/gtest.h>

using namespace crumple;

TEST(ContactInRun, FoldedLayersDoNotPassThrough) {
  crumple::testing::TinySheet t;
  MeshSpec spec;
  spec.shape = "square";
  spec.size = 0.1;
  spec.nodes = 120;
  spec.seed = 2;
  t.mesh = generate_mesh(spec);
  t.params.mass = 1e4 * 1400 * 2.5e-4 * 0.01 / t.mesh.num_nodes();
  t.info.mass = t.params.mass;
  t.info.area = t.mesh.total_area();
  t.info.spacing = t.mesh.mean_edge_length();
  t.settings.plastic_c0 = 0.3;
  SheetModel model(t.mesh, t.params);
  ContactSettings cs;
  cs.ks = t.params.ks;
  cs.sigma = 0.25 * t.mesh.mean_edge_length();
  // The site repulsion alone (no fold barrier): the test is about layers, not hinges.
  const SelfContact self(t.mesh, cs, false);
  self.add_to(model);
  const ContactTerm* contact = self.pairs.get();
  Integrator integ(model, t.settings);
  double dmin = 1e300;
  Eigen::Matrix3Xd pos;
  integ.before_step = [&](const State& s) {
    const bool changed = self.update(s.x);
    contact->sites().positions(s.x, pos);
    for (const auto& [a, b] : contact->candidates())
      if (contact->sites().interact(a, b)) dmin = std::min(dmin, (pos.col(a) - pos.col(b)).norm());
    return changed;
  };
  IntegratorStepper stepper(integ);
  // radius 0: the tethers aim the folded half exactly onto the other one.
  const YAML::Node stages = YAML::Load("[{type: fold, angle: 180, duration: 0.2, radius: 0}]");
  RunnerSettings rs;
  rs.quiet = true;
  rs.frame_dt = 1.0;
  ProtocolRunner runner(
      model, stepper,
      [&](int k) { return StageRegistry::builtin().make(stages[k], "layers.yaml", "stages"); }, 1,
      t.info, rs);
  crumple::testing::MemorySink sink;
  State s = model.rest_state();
  runner.run(s, sink);
  std::printf("smallest interacting site distance: %.3f sigma\n", dmin / cs.sigma);
  EXPECT_LT(dmin, cs.sigma) << "the layers never came into contact: the test proves nothing";
  EXPECT_GE(dmin, 0.3 * cs.sigma);
}
