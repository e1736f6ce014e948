// Stages and the runner on a tiny sheet: each stage alone does what it promises, one
// axial-crumpling cycle leaves creases (none before compression), and a run killed at a
// checkpoint and resumed ends bit for bit where the uninterrupted run ends (one thread).
#include "tests/protocols/runner_fixture.hpp"

#include <gtest/gtest.h>
#include <omp.h>

using namespace crumple;
using crumple::testing::MemorySink;
using crumple::testing::TinySheet;

namespace {

struct ProtocolRun {
  TinySheet sheet;
  std::unique_ptr<SheetModel> model;
  std::unique_ptr<Integrator> integ;
  std::unique_ptr<IntegratorStepper> stepper;
  YAML::Node stages;
  State state;
  MemorySink sink;

  ProtocolRun(const std::string& yaml, double c0 = 0.3) {
    sheet.settings.plastic_c0 = c0;
    model = std::make_unique<SheetModel>(sheet.mesh, sheet.params);
    integ = std::make_unique<Integrator>(*model, sheet.settings);
    stepper = std::make_unique<IntegratorStepper>(*integ);
    stages = YAML::Load(yaml);
    state = model->rest_state();
  }
  bool go(int cycles = 1, const Checkpoint* resume = nullptr, double ckpt_wall = 1e9) {
    RunnerSettings rs;
    rs.cycles = cycles;
    rs.frame_dt = 0.05;
    rs.quiet = true;
    rs.checkpoint_wall_s = ckpt_wall;
    rs.seed = 7;
    auto make = [this](int k) {
      return StageRegistry::builtin().make(stages[k], "t.yaml", "protocol.stages");
    };
    ProtocolRunner runner(*model, *stepper, make, static_cast<int>(stages.size()), sheet.info, rs);
    return runner.run(state, sink, resume);
  }
};

const char* kRoll = "[{type: roll, duration: 0.2, axis: fixed, angle: 30}]";
const char* kCycle = R"([{type: roll, duration: 0.2}, {type: compress, compaction: 0.4, speed: 0.2},
                          {type: release}, {type: unfold}])";

}  // namespace

TEST(Stages, RollPutsEveryNodeOnTheCylinder) {
  ProtocolRun r(kRoll);
  r.go();
  // The checkpoint taken when the roll ended holds the apparatus and the rolled state.
  const Checkpoint& c = r.sink.checkpoints.back();
  ASSERT_TRUE(c.apparatus.rolled);
  const double R = c.apparatus.radius;
  for (Index i = 0; i < r.model->num_nodes(); ++i) {
    const Vec3 d = node(c.state.x, i) - c.apparatus.axis_point;
    const double radial = (d - d.dot(c.apparatus.axis_dir) * c.apparatus.axis_dir).norm();
    EXPECT_NEAR(radial, R, 0.02 * R) << "node " << i;
  }
  EXPECT_NEAR(c.apparatus.axis_dir.dot(Vec3(std::cos(M_PI / 6), std::sin(M_PI / 6), 0)), 1.0,
              1e-12);
}

TEST(Stages, CompressStaysInsideAndReachesTheTarget) {
  ProtocolRun r(R"([{type: roll, duration: 0.2}, {type: compress, compaction: 0.4, speed: 0.2,
             clearance: 0.15}])");
  r.go();
  const Checkpoint& c = r.sink.checkpoints.back();
  const Apparatus& ap = c.apparatus;
  const double h = r.sheet.info.h_eff;
  double wmin = 1e9, wmax = -1e9;
  for (Index i = 0; i < r.model->num_nodes(); ++i) {
    const Vec3 d = node(c.state.x, i) - ap.axis_point;
    const double w = d.dot(ap.axis_dir);
    const double radial = (d - w * ap.axis_dir).norm();
    EXPECT_LE(radial, 1.15 * ap.radius + h) << "node " << i << " outside the container";
    wmin = std::min(wmin, w), wmax = std::max(wmax, w);
  }
  // Between the pistons, whose final gap is 0.4 H0 about the centre (walls are soft: allow h_eff).
  EXPECT_GE(wmin, -0.2 * ap.height - h);
  EXPECT_LE(wmax, 0.2 * ap.height + h);
  EXPECT_GE(wmax - wmin, 0.3 * ap.height);  // the sheet fills the gap: it was compressed
}

TEST(Stages, UnfoldFlattensAndKeepsPlasticityBelowYield) {
  ProtocolRun r(R"([{type: roll, duration: 0.2, radius: 0.1}, {type: unfold}])", 0.3);
  // A plastic field inside the yield band of the flat state (|c - p| < c0 throughout).
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(-0.08, 0.08);
  for (Index k = 0; k < r.state.p.size(); ++k) r.state.p[k] = U(rng);
  const VecX p0 = r.state.p;
  r.go();
  const State& s = r.state;
  double zmax = 0;
  for (Index i = 0; i < r.model->num_nodes(); ++i) zmax = std::max(zmax, std::abs(s.x[3 * i + 2]));
  EXPECT_LE(zmax, 2.0 * r.sheet.info.h_eff);
  double projected = 0;
  for (const auto& t : r.model->mesh().triangles) {
    const Vec3 a = node(s.x, t[0]), b = node(s.x, t[1]), c = node(s.x, t[2]);
    projected += 0.5 * std::abs((b - a).cross(c - a).z());
  }
  EXPECT_GE(projected, 0.9 * r.sheet.info.area);
  // No flow: p changes only by the round-off of the BDF sum (g = 0 exactly in the yield band).
  EXPECT_LE((s.p - p0).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Stages, OneCycleLeavesCreasesOnlyAfterCompression) {
  ProtocolRun r(kCycle, 0.3);
  r.go();
  const double threshold = 0.05;
  // Checkpoints: after roll (index 0), compress, release, then the end of the cycle.
  ASSERT_GE(r.sink.checkpoints.size(), 4u);
  EXPECT_LT(r.sink.checkpoints[0].state.p.cwiseAbs().maxCoeff(), threshold)
      << "plastic flow while rolling";
  ASSERT_EQ(r.sink.cycles.size(), 1u);
  const VecX& p = r.sink.cycles[0].p;
  EXPECT_GT((p.array().abs() > threshold).count(), 0) << "no crease after a crumpling cycle";
}

TEST(Runner, ResumeFromAnyCheckpointGivesTheUninterruptedResult) {
  omp_set_num_threads(1);
  const char* yaml = R"([{type: roll, duration: 0.2}, {type: compress, compaction: 0.5, speed: 0.3}])";
  ProtocolRun whole(yaml);
  whole.go(1, nullptr, 0.0);  // a checkpoint after every chunk
  const int n = static_cast<int>(whole.sink.checkpoints.size());
  ASSERT_GT(n, 6);
  for (int kill : {2, n / 2, n - 2}) {
    ProtocolRun killed(yaml);
    killed.sink.kill_after = kill;
    EXPECT_THROW(killed.go(1, nullptr, 0.0), MemorySink::Killed);
    const Checkpoint c = killed.sink.checkpoints.back();
    ProtocolRun resumed(yaml);
    resumed.go(1, &c, 0.0);
    SCOPED_TRACE("killed after checkpoint " + std::to_string(kill));
    EXPECT_EQ(resumed.state.t, whole.state.t);
    EXPECT_EQ((resumed.state.x - whole.state.x).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ((resumed.state.v - whole.state.v).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ((resumed.state.p - whole.state.p).cwiseAbs().maxCoeff(), 0.0);
  }
}
