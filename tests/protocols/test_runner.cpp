// Stages and the runner on a tiny sheet: each stage alone does what it promises, one
// axial-crumpling cycle leaves creases made by the compression (none before it, little after
// it), the runner reports every stage end, and a run
// killed at a checkpoint and resumed ends bit for bit where the uninterrupted run ends.
#include "tests/protocols/runner_fixture.hpp"

#include <gtest/gtest.h>
#include <omp.h>
#include <yaml-cpp/yaml.h>

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

  ProtocolRun(const std::string& yaml, double c0 = 0.3,
              const std::function<void(TinySheet&)>& tweak = {}) {
    sheet.settings.plastic_c0 = c0;
    if (tweak) tweak(sheet);
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

/// Total rest length of the hinges with |p| > threshold (the analysis's crease length).
double crease_length(const Mesh& mesh, const VecX& p, double threshold) {
  double l = 0;
  for (Index h = 0; h < p.size(); ++h)
    if (std::abs(p[h]) > threshold) l += mesh.rest_length[mesh.hinges[h].edge];
  return l;
}

const char* kRoll = "[{type: roll, duration: 0.2, axis: fixed, angle: 30}]";
// The roll radius keeps rolling elastic on this coarse grid (hinge curvature about edge / R
// below c0 = 0.3); the default radius would bend the 1 cm triangles past yield.
const char* kCycle = R"([{type: roll, duration: 0.2, radius: 0.05},
                          {type: compress, compaction: 0.4, speed: 0.2},
                          {type: release}, {type: unfold}])";

}  // namespace

TEST(Stages, RollPutsEveryNodeOnTheCylinder) {
  ProtocolRun r(kRoll);
  r.go();
  // The checkpoint taken when the roll ended holds the apparatus and the rolled state.
  const Checkpoint& c = r.sink.checkpoints.back();
  ASSERT_TRUE(c.apparatus.rolled);
  const double R = c.apparatus.radius;
  // The tethers are an elastic foundation of length xi = 0.05 sheet sizes (roll.cpp), softer
  // than this coarse grid (1 cm edges) at the grid scale: the stage ends when every node is
  // within half an edge of its target (tolerance x max(xi, edge)).
  const double tol = 0.5 * r.sheet.info.spacing;
  double mean_dev = 0;
  for (Index i = 0; i < r.model->num_nodes(); ++i) {
    const Vec3 d = node(c.state.x, i) - c.apparatus.axis_point;
    const double radial = (d - d.dot(c.apparatus.axis_dir) * c.apparatus.axis_dir).norm();
    EXPECT_NEAR(radial, R, tol) << "node " << i;
    mean_dev += std::abs(radial - R) / r.model->num_nodes();
  }
  EXPECT_LT(mean_dev, 0.05 * R);
  EXPECT_NEAR(c.apparatus.axis_dir.dot(Vec3(std::cos(M_PI / 6), std::sin(M_PI / 6), 0)), 1.0,
              1e-12);
}

// axis: side draws each cycle's roll axis between the sheet's two sides, `angle` and `angle` +
// 90 degrees, and nothing in between (docs/studies/roll_axis/): over eight seeded cycles both
// sides occur and every axis is one of them; the stage reports each cycle's axis as it rolled
// (what the run file records), and the unfold reports none.
TEST(Stages, RollAboutARandomSide) {
  ProtocolRun r(R"([{type: roll, duration: 0.2, radius: 0.05, axis: side, angle: 10},
                    {type: unfold, open_time: 0.1, max_duration: 0.3}])");
  r.go(8);
  const Vec3 s0(std::cos(M_PI / 18), std::sin(M_PI / 18), 0);
  const Vec3 s1(-std::sin(M_PI / 18), std::cos(M_PI / 18), 0);
  int rolls = 0, first = 0, second = 0;
  for (const Checkpoint& c : r.sink.checkpoints) {
    if (!c.apparatus.rolled || c.stage != 1 || c.in_stage) continue;  // as the roll ended
    ++rolls;
    const Vec3 a = c.apparatus.axis_dir;
    const bool on0 = std::abs(std::abs(a.dot(s0)) - 1.0) < 1e-12;
    const bool on1 = std::abs(std::abs(a.dot(s1)) - 1.0) < 1e-12;
    EXPECT_TRUE(on0 || on1) << "axis " << a.transpose() << " is along neither side";
    first += on0, second += on1;
  }
  EXPECT_EQ(rolls, 8);
  EXPECT_GT(first, 0);
  EXPECT_GT(second, 0);
  int reported = 0;
  for (const auto& e : r.sink.stage_ends) {
    if (e.type != "roll") {
      EXPECT_FALSE(e.roll_axis_deg.has_value()) << e.type;
      continue;
    }
    ASSERT_TRUE(e.roll_axis_deg.has_value());
    // The axis the apparatus holds from this cycle's roll (the checkpoint as the roll ended).
    const Checkpoint* at_end = nullptr;
    for (const Checkpoint& c : r.sink.checkpoints)
      if (c.apparatus.rolled && c.stage == 1 && !c.in_stage && c.cycle == e.cycle) at_end = &c;
    ASSERT_NE(at_end, nullptr) << "cycle " << e.cycle;
    const double deg = *e.roll_axis_deg;
    EXPECT_TRUE(std::abs(deg - 10.0) < 1e-9 || std::abs(deg - 100.0) < 1e-9) << deg;
    const Vec3 a(std::cos(deg * M_PI / 180), std::sin(deg * M_PI / 180), 0);
    EXPECT_NEAR(std::abs(a.dot(at_end->apparatus.axis_dir)), 1.0, 1e-12);
    ++reported;
  }
  EXPECT_EQ(reported, 8);
}

TEST(Stages, CompressStaysInsideAndReachesTheTarget) {
  ProtocolRun r(R"([{type: roll, duration: 0.2}, {type: compress, compaction: 0.4, speed: 0.2,
             clearance: 0.15, retract: false}])");
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

// A list of compaction ratios gives one per cycle, the last holding for later cycles: each
// cycle's pistons close to its own gap, and the stage reports that cycle's ratio.
TEST(Stages, CompactionListGivesOnePerCycle) {
  ProtocolRun r(R"([{type: roll, duration: 0.2, axis: fixed}, {type: compress, compaction: [0.6, 0.4],
             speed: 0.4, retract: false}])");
  r.go(3);
  std::vector<double> reported;
  for (const auto& e : r.sink.stage_ends)
    if (e.type == "compress") reported.push_back(e.compaction.value_or(-1));
  EXPECT_EQ(reported, (std::vector<double>{0.6, 0.4, 0.4}));
  // Each cycle's end state lies between its own pistons (the pistons stay closed: retract off).
  std::vector<double> extent;
  for (const auto& e : r.sink.stage_ends) {
    if (e.type != "compress") continue;
    double wmin = 1e9, wmax = -1e9;
    for (Index i = 0; i < r.model->num_nodes(); ++i) {
      const double w = node(e.state.x, i).dot(r.sink.checkpoints.back().apparatus.axis_dir);
      wmin = std::min(wmin, w), wmax = std::max(wmax, w);
    }
    extent.push_back(wmax - wmin);
  }
  ASSERT_EQ(extent.size(), 3u);
  EXPECT_GT(extent[0], extent[1] * 1.2);  // 0.6 H0 against 0.4 H0
  // Bad lists are refused with the element named.
  const auto refuse = [](const std::string& value) {
    try {
      StageRegistry::builtin().make(
          YAML::Load("{type: compress, compaction: " + value + "}"), "t.yaml", "protocol.stages[1]");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refuse("[0.5, 1.5]").find("compaction: element 2 must be > 0 and <= 1, got 1.5"),
            std::string::npos);
  EXPECT_NE(refuse("[0.5, x]").find("element 2: expected a number, got 'x'"), std::string::npos);
  EXPECT_NE(refuse("[]").find("expected a number or a non-empty list"), std::string::npos);
}

TEST(Stages, RollAndUnfoldWithoutCompressionMakeNoCrease) {
  ProtocolRun r(R"([{type: roll, duration: 0.2, radius: 0.1}, {type: unfold}])", 0.3);
  // A plastic field inside the yield band of the flat state (|c - p| < c0 throughout).
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(-0.08, 0.08);
  for (Index k = 0; k < r.state.p.size(); ++k) r.state.p[k] = U(rng);
  const VecX p0 = r.state.p;
  r.go();
  const State& s = r.state;
  // Laid out near flat: within a few sheet thicknesses of the plane, covering the sheet's area.
  double zmin = 1e9, zmax = -1e9;
  for (Index i = 0; i < r.model->num_nodes(); ++i)
    zmin = std::min(zmin, s.x[3 * i + 2]), zmax = std::max(zmax, s.x[3 * i + 2]);
  EXPECT_LE(zmax - zmin, 4.0 * r.sheet.info.h_eff);
  double projected = 0;
  for (const auto& t : r.model->mesh().triangles) {
    const Vec3 a = node(s.x, t[0]), b = node(s.x, t[1]), c = node(s.x, t[2]);
    projected += 0.5 * std::abs((b - a).cross(c - a).z());
  }
  EXPECT_GE(projected, 0.95 * r.sheet.info.area);
  // No flow: p changes only by the round-off of the BDF sum (g = 0 exactly in the yield band),
  // so no hinge crosses the crease threshold (half of c0, analysis/README.md) it started below.
  EXPECT_LE((s.p - p0).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT(s.p.cwiseAbs().maxCoeff(), 0.5 * 0.3);
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

TEST(Stages, CyclesCreasesAreMadeByTheCompression) {
  ProtocolRun r(kCycle, 0.3);
  r.go();
  ASSERT_EQ(r.sink.stage_ends.size(), 4u);
  const char* types[] = {"roll", "compress", "release", "unfold"};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(r.sink.stage_ends[k].cycle, 1);
    EXPECT_EQ(r.sink.stage_ends[k].index, k);
    EXPECT_EQ(r.sink.stage_ends[k].type, types[k]);
    // Only the compress stage compacts the sheet, and it reports the compaction it was given.
    if (k == 1)
      EXPECT_EQ(r.sink.stage_ends[k].compaction, YAML::Load(kCycle)[1]["compaction"].as<double>());
    else
      EXPECT_FALSE(r.sink.stage_ends[k].compaction.has_value()) << types[k];
  }
  ASSERT_EQ(r.sink.cycles.size(), 1u);
  EXPECT_EQ(r.sink.stage_ends[3].state.p, r.sink.cycles[0].p);
  const Mesh& mesh = r.model->mesh();
  const double threshold = 0.5 * 0.3;
  const double after_compress = crease_length(mesh, r.sink.stage_ends[1].state.p, threshold);
  const double after_release = crease_length(mesh, r.sink.stage_ends[2].state.p, threshold);
  const double after_unfold = crease_length(mesh, r.sink.stage_ends[3].state.p, threshold);
  ASSERT_GT(after_compress, 0.0) << "the compression made no crease";
  // Unfolding a creased sheet adds less than 10 % to its crease length.
  EXPECT_LT(after_unfold, 1.1 * after_release)
      << "release " << after_release << ", unfold " << after_unfold;
  // Most of the cycle's creases were made while the sheet was crushed.
  EXPECT_LT(after_unfold - after_compress, 0.15 * after_unfold)
      << "compress " << after_compress << ", cycle end " << after_unfold;
}

TEST(Stages, ReleaseEndsByQuiescenceWhileTheSheetDrifts) {
  // A flat, unstressed sheet drifting and spinning slowly as a whole: without drag the drift
  // never decays, and the integrator is kept explicit so that it is not projected away.
  ProtocolRun r(R"([{type: release, max_duration: 1.0, min_duration: 0.02}])", 0.3,
                [](TinySheet& t) {
                  t.params.b_iso = 0.0;
                  t.settings.mode_initial = IntegrationMode::Explicit;
                  t.settings.switch_down = 0.0;
                });
  const Vec3 V(0.03, -0.02, 0.01), w(0.0, 0.0, 0.1);
  const Vec3 centre = r.model->mesh().ref.rowwise().mean();
  for (Index i = 0; i < r.model->num_nodes(); ++i)
    node(r.state.v, i) = V + w.cross(node(r.state.x, i) - centre);
  r.go();
  EXPECT_LT(r.state.t, 0.1) << "release waited for the rigid drift to stop";
  double vmax = 0;
  for (Index i = 0; i < r.model->num_nodes(); ++i) vmax = std::max(vmax, node(r.state.v, i).norm());
  EXPECT_GT(vmax / r.sheet.info.size, 0.2) << "the drift itself decayed";
}

TEST(Stages, RollKeepsTheCreasesOfEarlierCycles) {
  // A sheet carrying one straight crease (p = 0.8 > c0 on the hinges along x = size/2, which the
  // roll about the x axis does not bend) is rolled. Stiff tethers (flatten_length 0.009: about
  // the 0.1 ks of earlier versions on this grid) hold those hinges near c = 0 and bend them back
  // past yield, p down towards c0; the default soft tethers let more of the fold stand. A
  // single crease across the whole sheet is a global fold that any tethering towards the roll
  // resists, so part of it still flows back.
  auto lowest_after_roll = [](const std::string& flatten_length) {
    ProtocolRun r("[{type: roll, duration: 0.2, radius: 0.1, axis: fixed, angle: 0, "
                  "flatten_length: " + flatten_length + "}]", 0.3,
                  [](TinySheet& t) {
                    t = TinySheet(31);
                    t.settings.plastic_c0 = 0.3;
                  });
    const Mesh& mesh = r.model->mesh();
    const double size = r.sheet.info.size, h = r.sheet.info.spacing;
    std::vector<Index> crease;
    for (Index k = 0; k < mesh.num_hinges(); ++k) {
      const auto& e = mesh.edges[mesh.hinges[k].edge];
      const Vec3 a = mesh.ref.col(e[0]), b = mesh.ref.col(e[1]);
      if (std::abs(0.5 * (a.x() + b.x()) - 0.5 * size) < 0.3 * h &&
          std::abs(b.y() - a.y()) > 2.0 * std::abs(b.x() - a.x()))
        crease.push_back(k);
    }
    EXPECT_GE(crease.size(), 20u);
    for (Index k : crease) r.state.p[k] = 0.8;
    r.go();
    double lowest = 1e9;
    for (Index k : crease) lowest = std::min(lowest, std::abs(r.state.p[k]));
    return lowest;
  };
  const double stiff = lowest_after_roll("0.009"), soft = lowest_after_roll("0.05");
  std::printf("lowest |p| on the crease after the roll: stiff tethers %.3f, soft %.3f\n", stiff,
              soft);
  EXPECT_GT(soft, stiff + 0.1);
  EXPECT_GT(soft, 0.3 + 0.1) << "the soft roll flattened the crease back to yield";
}
