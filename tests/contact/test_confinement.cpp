// Self-avoidance under radial confinement (paper Fig. 5a, 8c): after the cutoff radius has
// crumpled the disk, no two non-adjacent triangles intersect. The fast test uses a small disk
// and a short compression; the `slow` one the 3000-node sheet confined into a ball.
#include "sim/contact/contact_term.hpp"
#include "sim/mesh/generate.hpp"
#include "tests/protocols/runner_fixture.hpp"
#include "tests/support/self_intersection.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

using namespace crumple;

namespace {
// Returns the final state of a disk of `nodes` nodes confined for `duration` seconds.
std::pair<Mesh, State> confine(int nodes, double duration, bool with_contact) {
  crumple::testing::TinySheet t;
  MeshSpec spec;
  spec.shape = "disk";
  spec.size = 0.1;
  spec.nodes = nodes;
  spec.seed = 1;
  t.mesh = generate_mesh(spec);
  t.params.mass = 1e4 * 1400 * 2.5e-4 * t.mesh.total_area() / t.mesh.num_nodes();
  t.info.mass = t.params.mass;
  t.info.area = t.mesh.total_area();
  t.info.spacing = t.mesh.mean_edge_length();
  t.settings.plastic_c0 = 0.3;
  SheetModel model(t.mesh, t.params);
  std::shared_ptr<ContactTerm> contact;
  Integrator integ(model, t.settings);
  if (with_contact) {
    ContactSettings cs;
    cs.ks = t.params.ks;
    cs.sigma = std::max(t.info.h_eff, 0.5 * t.mesh.mean_edge_length());
    contact = std::make_shared<ContactTerm>(t.mesh, cs);
    model.add_term(contact, TermKind::Contact);
    integ.before_step = [&](const State& s) {
      const std::size_t n = contact->stats().searches;
      contact->update(s.x);
      return contact->stats().searches != n;
    };
  }
  IntegratorStepper stepper(integ);
  const YAML::Node stages = YAML::Load("[{type: radial_confine, speed: 0.01, duration: " +
                                       std::to_string(duration) + "}]");
  RunnerSettings rs;
  rs.quiet = true;
  rs.frame_dt = 10.0;
  ProtocolRunner runner(
      model, stepper,
      [&](int k) { return StageRegistry::builtin().make(stages[k], "radial.yaml", "stages"); }, 1,
      t.info, rs);
  crumple::testing::MemorySink sink;
  State s = model.rest_state();
  runner.run(s, sink);
  return {t.mesh, s};
}
double extent(const State& s) {
  double r = 0;
  for (Index i = 0; i < s.x.size() / 3; ++i) r = std::max(r, node(s.x, i).head<2>().norm());
  return r;
}
}  // namespace

TEST(Confinement, SmallDiskStaysFreeOfSelfIntersections) {
  const auto [mesh, s] = confine(250, 2.5, true);
  EXPECT_LT(extent(s), 0.04) << "the disk was not confined";
  const std::size_t n = crumple::testing::count_self_intersections(mesh, s.x);
  std::printf("with contact: %zu intersecting pairs, extent %.4f\n", n, extent(s));
  EXPECT_EQ(n, 0u);
}

TEST(Confinement, DetectorSeesThePhantomSheetPassThroughItself) {
  // Without contact the same compression makes the sheet pass through itself: the check is
  // able to fail.
  const auto [mesh, s] = confine(250, 2.5, false);
  const std::size_t n = crumple::testing::count_self_intersections(mesh, s.x);
  std::printf("phantom: %zu intersecting pairs, extent %.4f\n", n, extent(s));
  EXPECT_GT(n, 0u);
}

TEST(ConfinementSlow, SheetOf3000NodesConfinedIntoABall) {
  const char* nodes = std::getenv("CRUMPLE_CONFINE_NODES");
  const auto [mesh, s] = confine(nodes ? std::atoi(nodes) : 3000, 4.0, true);
  EXPECT_EQ(crumple::testing::count_self_intersections(mesh, s.x), 0u);
}
