// Single fold (paper Fig. 3b): a square sheet folded in half and released keeps a fold whose
// final angle decreases monotonically with the yield curvature c0, at two mesh resolutions.
// Prints c_f against beta (c0 - alpha), alpha = 0.05, beta = 0.04 lambda (lambda = sqrt(n/A) in
// the run's length unit), the paper's collapse variables.
#include "sim/mesh/generate.hpp"
#include "tests/protocols/runner_fixture.hpp"

#include <gtest/gtest.h>

using namespace crumple;

namespace {
// Angle between the mean normals of the two halves, away from the fold line.
double fold_angle(const Mesh& m, const State& s) {
  Vec3 n1 = Vec3::Zero(), n2 = Vec3::Zero();
  for (const auto& t : m.triangles) {
    const double cx = (m.ref(0, t[0]) + m.ref(0, t[1]) + m.ref(0, t[2])) / 3.0;
    const Vec3 a = node(s.x, t[0]), b = node(s.x, t[1]), c = node(s.x, t[2]);
    const Vec3 n = (b - a).cross(c - a).normalized();
    if (cx < -0.02) n1 += n;
    if (cx > 0.02) n2 += n;
  }
  return std::acos(std::clamp(n1.normalized().dot(n2.normalized()), -1.0, 1.0));
}

double fold_and_release(int nodes, double c0) {
  crumple::testing::TinySheet t;
  MeshSpec spec;
  spec.shape = "square";
  spec.size = 0.1;
  spec.nodes = nodes;
  spec.seed = 3;
  t.mesh = generate_mesh(spec);
  t.params.mass = 1e4 * 1400 * 2.5e-4 * 0.01 / t.mesh.num_nodes();
  t.info.mass = t.params.mass;
  t.info.area = t.mesh.total_area();
  t.info.spacing = t.mesh.mean_edge_length();
  t.settings.plastic_c0 = c0;
  t.settings.plastic_rate = 5.0;
  SheetModel model(t.mesh, t.params);
  Integrator integ(model, t.settings);
  IntegratorStepper stepper(integ);
  const YAML::Node stages = YAML::Load(
      "[{type: fold, angle: 180, duration: 0.3}, {type: release, max_duration: 2}]");
  RunnerSettings rs;
  rs.quiet = true;
  rs.frame_dt = 1.0;
  ProtocolRunner runner(
      model, stepper,
      [&](int k) { return StageRegistry::builtin().make(stages[k], "fold.yaml", "stages"); }, 2,
      t.info, rs);
  crumple::testing::MemorySink sink;
  State s = model.rest_state();
  runner.run(s, sink);
  const double theta = fold_angle(t.mesh, s);
  const double lambda = std::sqrt(t.mesh.num_nodes() / t.info.area);
  std::printf("single fold: %4d nodes  c0 %.2f  theta_f %6.1f deg  c_f %.3f  beta(c0-alpha) %.2f\n",
              t.mesh.num_nodes(), c0, theta * 180 / M_PI, 2 * std::sin(theta / 2),
              0.04 * lambda * (c0 - 0.05));
  return theta;
}
}  // namespace

TEST(SingleFold, FinalAngleDecreasesWithYieldCurvature) {
  for (int nodes : {150, 300}) {
    double previous = M_PI + 1e-9;
    for (double c0 : {0.1, 0.6, 1.4}) {
      const double theta = fold_and_release(nodes, c0);
      EXPECT_LT(theta, previous) << nodes << " nodes, c0 = " << c0;
      EXPECT_GT(theta, 0.3) << "no fold kept at all";
      previous = theta;
    }
  }
}
