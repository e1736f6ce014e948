// Self-avoidance under radial confinement (paper Fig. 5a, 8c): after the cutoff radius has
// crumpled the disk, no two non-adjacent triangles intersect. The fast test uses a small disk
// and a short compression; the `slow` one the 3000-node sheet confined into a ball.
#include "sim/assemble/sheet_setup.hpp"
#include "sim/contact/self_contact.hpp"
#include "sim/model/hinge_geometry.hpp"
#include "sim/mesh/generate.hpp"
#include "tests/protocols/runner_fixture.hpp"
#include "tests/support/self_intersection.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

using namespace crumple;

namespace {
// Returns the final state of a disk of `nodes` nodes confined for `duration` seconds.
std::pair<Mesh, State> confine(int nodes, double duration, bool with_contact) {
  crumple::testing::TinySheet t;
  t.mesh = generate_mesh(MeshSpec{"disk", 0.1, nodes, 1});
  t.params.mass = 1e4 * 1400 * 2.5e-4 * t.mesh.total_area() / t.mesh.num_nodes();
  t.info.mass = t.params.mass;
  t.info.area = t.mesh.total_area();
  t.info.spacing = t.mesh.mean_edge_length();
  t.settings.plastic_c0 = 0.3;
  SheetModel model(t.mesh, t.params);
  std::unique_ptr<SelfContact> contact;
  Integrator integ(model, t.settings);
  if (with_contact) {
    // The simulator's default contact (range rule of sim/assemble/sheet_setup.hpp).
    ResolvedMaterial mat;
    mat.model = t.params;
    mat.h_eff = t.info.h_eff;
    const ContactSettings cs = contact_settings(ContactParams{}, t.mesh, mat);
    contact = std::make_unique<SelfContact>(t.mesh, cs, ContactParams{}.fold_barrier);
    contact->add_to(model);
    integ.before_step = [&](const State& s) { return contact->update(s.x); };
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
// On failure: each crossing pair with its nodes (b: on the border), the smallest distance
// between their nodes now and in the reference sheet, against the mean edge.
void describe_crossings(const Mesh& mesh, const VecX& x) {
  for (auto [a, b] : crumple::testing::self_intersections(mesh, x)) {
    double now = 1e300, ref = 1e300;
    for (Index i : mesh.triangles[a])
      for (Index j : mesh.triangles[b]) {
        now = std::min(now, (node(x, i) - node(x, j)).norm());
        ref = std::min(ref, (mesh.ref.col(i) - mesh.ref.col(j)).norm());
      }
    std::printf("  crossing triangles %ld and %ld:", static_cast<long>(a), static_cast<long>(b));
    for (Index t : {a, b})
      for (Index i : mesh.triangles[t])
        std::printf(" %ld%s", static_cast<long>(i), mesh.boundary[i] ? "b" : "");
    // The sharpest fold nearby: the largest |bend angle| of the hinges touching either.
    double fold = 0;
    for (const Hinge& h : mesh.hinges) {
      bool near = false;
      for (Index i : h.nodes)
        for (Index t : {a, b})
          for (Index j : mesh.triangles[t]) near = near || i == j;
      if (near)
        fold = std::max(fold, std::abs(bend_angle(node(x, h.nodes[0]), node(x, h.nodes[1]),
                                                  node(x, h.nodes[2]), node(x, h.nodes[3]))));
    }
    std::printf("; nearest nodes %.3g now, %.3g in the reference (edge %.3g); sharpest fold "
                "nearby %.1f deg\n", now, ref, mesh.mean_edge_length(), fold * 180 / M_PI);
  }
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
  describe_crossings(mesh, s.x);
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
  const std::size_t n = crumple::testing::count_self_intersections(mesh, s.x);
  std::printf("with contact: %zu intersecting pairs, extent %.4f\n", n, extent(s));
  describe_crossings(mesh, s.x);
  EXPECT_EQ(n, 0u);
}
