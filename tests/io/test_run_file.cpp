// The run file: an exact HDF5 round trip of mesh, frames, cycles, log, meta, costs and
// checkpoint; the compaction recorded per stage end and per cycle (and by the sink); older files
// without the logged average, the stage walls, the costs or the compaction; write failures; bad
// files.
#include "protocols/stage.hpp"
#include "sim/core/errors.hpp"
#include "sim/io/h5.hpp"
#include "sim/apps/run_sink.hpp"
#include "sim/io/run_file.hpp"
#include "tests/support/grid_mesh.hpp"
#include "tests/support/scratch.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <random>

using namespace crumple;

TEST(RunFile, RoundTripIsExact) {
  RunRecord r;
  r.mesh = crumple::testing::grid_mesh(5, 4, 0.1, 0.08, 0.2, 3);
  r.config = "mesh: {nodes: 20}\n";
  r.meta.program_version = "9.9";
  r.meta.git_revision = "abc";
  r.meta.seed = 1234567890123ULL;
  r.meta.ks = 1.5, r.meta.kb = 2.5e-3, r.meta.mass = 1e-7, r.meta.h_eff = 2.5e-4;
  std::mt19937_64 rng(1);
  std::normal_distribution<double> N;
  auto random_vec = [&](Index n) {
    VecX v(n);
    for (Index k = 0; k < n; ++k) v[k] = N(rng);
    return v;
  };
  const Index n3 = 3 * r.mesh.num_nodes(), nh = r.mesh.num_hinges();
  for (int k = 0; k < 3; ++k) r.frames.push_back({State{random_vec(n3), random_vec(n3), random_vec(nh), 0.1 * k}, "roll", 1, 10L * k});
  CycleRecord c{1, 2.5, random_vec(n3), random_vec(nh), 0.35};
  r.cycles.push_back(c);
  r.stage_ends.push_back({1, 0, "roll", 0.2, random_vec(nh)});
  r.stage_ends.back().roll_axis_deg = 123.5;
  r.stage_ends.push_back({1, 1, "compress", 1.25, random_vec(nh), 12.5, 0.35});
  LogRow row;
  row.t = 0.3, row.h = 1e-3, row.mode = 1, row.newton_iters = 2, row.cg_iters = 40, row.e_bend = 7;
  row.order = 3, row.a_ratio = 2e-3, row.a_ratio_avg = 1.5e-3;
  r.log = {row, row};
  IntegratorSummary sum;
  sum.steps_implicit = 5, sum.steps_explicit = 7, sum.cg_iters = 123456789012;
  sum.wall_linear = 0.25;
  r.summary = sum;
  r.costs = RunCosts{1.5, 2.25, 9876543210L, 0.125};
  // The run file stores restart entries of every kind without knowing whose they are.
  RestartData ck;
  ck.ints["cycle"] = 2;
  ck.reals["stage_t_begin"] = 1.25;
  ck.texts["rng_at_stage_begin"] = "1 2 3";
  ck.arrays["stepper"] = {1, 2, 3.5};
  ck.states["state"] = r.frames[1].state;
  ck.states["stage_begin"] = r.frames[0].state;
  r.checkpoint = ck;

  const std::string path = crumple::testing::scratch_path("roundtrip.h5").string();
  write_run_file_atomic(path, r);
  const RunRecord q = read_run_file(path);
  std::filesystem::remove(path);

  EXPECT_EQ(q.config, r.config);
  EXPECT_EQ(q.meta.seed, r.meta.seed);
  EXPECT_EQ(q.meta.git_revision, "abc");
  EXPECT_EQ(q.meta.kb, 2.5e-3);
  EXPECT_EQ(q.mesh.ref, r.mesh.ref);
  EXPECT_EQ(q.mesh.triangles, r.mesh.triangles);
  EXPECT_EQ(q.mesh.num_hinges(), r.mesh.num_hinges());
  ASSERT_EQ(q.frames.size(), 3u);
  EXPECT_EQ(q.frames[2].state.x, r.frames[2].state.x);
  EXPECT_EQ(q.frames[2].state.p, r.frames[2].state.p);
  EXPECT_EQ(q.frames[2].state.t, r.frames[2].state.t);
  EXPECT_EQ(q.frames[2].step, 20);
  ASSERT_EQ(q.cycles.size(), 1u);
  EXPECT_EQ(q.cycles[0].p, c.p);
  EXPECT_EQ(q.cycles[0].compaction, c.compaction);
  ASSERT_EQ(q.stage_ends.size(), 2u);
  EXPECT_EQ(q.stage_ends[1].p, r.stage_ends[1].p);
  EXPECT_EQ(q.stage_ends[1].stage, "compress");
  EXPECT_EQ(q.stage_ends[1].stage_index, 1);
  EXPECT_EQ(q.stage_ends[1].cycle, 1);
  EXPECT_EQ(q.stage_ends[1].t, 1.25);
  EXPECT_EQ(q.stage_ends[1].wall, 12.5);
  EXPECT_TRUE(std::isnan(q.stage_ends[0].wall));  // not measured: stays NaN
  EXPECT_EQ(q.stage_ends[1].compaction, r.stage_ends[1].compaction);
  EXPECT_FALSE(q.stage_ends[0].compaction.has_value());  // the roll compacts nothing
  EXPECT_EQ(q.stage_ends[0].roll_axis_deg, 123.5);
  EXPECT_FALSE(q.stage_ends[1].roll_axis_deg.has_value());  // the compress rolls nothing
  ASSERT_EQ(q.log.size(), 2u);
  EXPECT_EQ(q.log[1].cg_iters, 40);
  EXPECT_EQ(q.log[1].e_bend, 7);
  EXPECT_EQ(q.log[1].order, 3);
  EXPECT_EQ(q.log[1].a_ratio, 2e-3);
  EXPECT_EQ(q.log[1].a_ratio_avg, 1.5e-3);
  ASSERT_TRUE(q.summary.has_value());
  EXPECT_EQ(q.summary->steps_implicit, 5);
  EXPECT_EQ(q.summary->steps_explicit, 7);
  EXPECT_EQ(q.summary->cg_iters, 123456789012);
  EXPECT_EQ(q.summary->wall_linear, 0.25);
  ASSERT_TRUE(q.costs.has_value());
  EXPECT_EQ(q.costs->contact_search_s, 1.5);
  EXPECT_EQ(q.costs->contact_eval_s, 2.25);
  EXPECT_EQ(q.costs->contact_searches, 9876543210L);
  EXPECT_EQ(q.costs->output_s, 0.125);
  ASSERT_TRUE(q.checkpoint.has_value());
  EXPECT_EQ(q.checkpoint->state("stage_begin").x, r.frames[0].state.x);
  EXPECT_EQ(q.checkpoint->state("state").t, r.frames[1].state.t);
  EXPECT_EQ(q.checkpoint->array("stepper"), ck.arrays["stepper"]);
  EXPECT_EQ(q.checkpoint->integer("cycle"), 2);
  EXPECT_EQ(q.checkpoint->real("stage_t_begin"), 1.25);
  EXPECT_EQ(q.checkpoint->text("rng_at_stage_begin"), "1 2 3");
  EXPECT_EQ(q.checkpoint->ints.size(), 1u);  // nothing added, nothing lost
  EXPECT_EQ(q.checkpoint->reals.size(), 1u);
  EXPECT_EQ(q.checkpoint->texts.size(), 1u);
  EXPECT_EQ(q.checkpoint->arrays.size(), 1u);
  EXPECT_EQ(q.checkpoint->states.size(), 2u);
  // A missing entry names the file and the entry.
  try {
    (void)q.checkpoint->integer("stage");
    FAIL() << "a missing entry must throw";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": /checkpoint@stage: missing");
  }
}

// The cycle's compaction is the strongest (smallest) that a stage of that cycle reported; NaN
// when none did. A cycle written as such (NaN) and one of a file from before the attribute
// existed both read back as NaN.
TEST(RunFile, CycleCompactionFromItsStageEnds) {
  const VecX p;
  std::vector<StageEndRecord> ends = {{1, 0, "roll", 0.1, p},
                                      {1, 1, "compress", 0.2, p, NAN, 0.4},
                                      {1, 2, "compress", 0.3, p, NAN, 0.25},
                                      {1, 3, "unfold", 0.4, p},
                                      {2, 0, "roll", 0.5, p},
                                      {2, 1, "compress", 0.6, p, NAN, 0.6},
                                      {3, 0, "roll", 0.7, p}};
  EXPECT_EQ(cycle_compaction(ends, 1), 0.25);
  EXPECT_EQ(cycle_compaction(ends, 2), 0.6);
  EXPECT_TRUE(std::isnan(cycle_compaction(ends, 3)));  // no compacting stage
  EXPECT_TRUE(std::isnan(cycle_compaction(ends, 4)));  // no stage at all

  RunRecord r;
  r.mesh = crumple::testing::grid_mesh(3, 3, 0.1, 0.1, 0.0, 1);
  const Index n3 = 3 * r.mesh.num_nodes(), nh = r.mesh.num_hinges();
  CycleRecord c{1, 1.0, VecX::Zero(n3), VecX::Zero(nh)};
  r.cycles = {c, c};
  r.cycles[0].compaction = 0.3;
  r.cycles[1].cycle = 2;  // compaction left NaN: no compacting stage
  const std::string path = (std::filesystem::temp_directory_path() / "crumple_compaction.h5").string();
  write_run_file(path, r);
  const RunRecord q = read_run_file(path);
  ASSERT_EQ(q.cycles.size(), 2u);
  EXPECT_EQ(q.cycles[0].compaction, 0.3);
  EXPECT_TRUE(std::isnan(q.cycles[1].compaction));
  {
    H5::H5File f(path, H5F_ACC_RDWR);
    f.openGroup("cycles/0001").removeAttr("compaction");  // written before it was recorded
  }
  EXPECT_TRUE(std::isnan(read_run_file(path).cycles[0].compaction));
  std::filesystem::remove(path);
}

namespace {
/// A stage that does nothing, of a given type and compaction, for the sink's stage ends.
struct FixedStage : Stage {
  std::string name;
  std::optional<double> ratio;
  FixedStage(std::string n, std::optional<double> r) : name(std::move(n)), ratio(r) {}
  std::string type() const override { return name; }
  void begin(StageContext&) override {}
  bool done(StageContext&) override { return true; }
  std::optional<double> compaction() const override { return ratio; }
};
}  // namespace

// The run file's sink records what each stage reported and gives the cycle the compaction of
// its stage ends, those it holds from before a resume included: here the compress stage of
// cycle 1 ended in the process that wrote the checkpoint, and this one only ends the cycle.
TEST(RunFile, SinkTakesTheCycleCompactionFromItsStageEnds) {
  SheetModel model(crumple::testing::grid_mesh(3, 3, 0.1, 0.1, 0.0, 1), ModelParams{});
  Integrator integ(model, IntegratorSettings{});
  RunRecord rec;
  rec.mesh = model.mesh();
  const State s = model.rest_state();
  rec.stage_ends.push_back({1, 0, "roll", 0.1, s.p});
  rec.stage_ends.push_back({1, 1, "compress", 0.2, s.p, NAN, 0.4});  // read back on resume
  const std::string path = (std::filesystem::temp_directory_path() / "crumple_sink.h5.tmp").string();
  FileSink sink(rec, path, integ);
  sink.stage_end(1, 2, FixedStage("unfold", std::nullopt), s);
  sink.cycle_end(1, s);
  sink.stage_end(2, 0, FixedStage("roll", std::nullopt), s);
  sink.stage_end(2, 1, FixedStage("compress", 0.3), s);
  sink.cycle_end(2, s);
  sink.stage_end(3, 0, FixedStage("roll", std::nullopt), s);
  sink.cycle_end(3, s);
  ASSERT_EQ(rec.cycles.size(), 3u);
  EXPECT_EQ(rec.cycles[0].compaction, 0.4);
  EXPECT_EQ(rec.cycles[1].compaction, 0.3);
  EXPECT_TRUE(std::isnan(rec.cycles[2].compaction));  // no compacting stage in cycle 3
  EXPECT_EQ(rec.stage_ends[4].compaction, 0.3);
  EXPECT_FALSE(rec.stage_ends[2].compaction.has_value());
}

// A file written before the moving average was logged reads with NaN in its place; a column
// of the wrong length is bad input that names the file.
TEST(RunFile, OlderLogWithoutTheAverageAndUnequalColumns) {
  RunRecord r;
  r.mesh = crumple::testing::grid_mesh(3, 3, 0.1, 0.1, 0.0, 1);
  LogRow row;
  row.t = 0.5, row.a_ratio = 1e-4, row.a_ratio_avg = 2e-4;
  r.log = {row, row, row};
  r.stage_ends.push_back({1, 0, "roll", 0.2, VecX::Zero(r.mesh.num_hinges()), 3.0});
  const std::string path = crumple::testing::scratch_path("oldlog.h5").string();
  write_run_file(path, r);
  {
    H5::H5File f(path, H5F_ACC_RDWR);
    H5::Group log = f.openGroup("log");
    ASSERT_GE(H5Ldelete(log.getId(), "a_ratio_avg", H5P_DEFAULT), 0);
    H5::Group end = f.openGroup("stage_ends/000000");
    end.removeAttr("wall");  // written before the stage walls were stored
  }
  const RunRecord older = read_run_file(path);
  ASSERT_EQ(older.stage_ends.size(), 1u);
  EXPECT_TRUE(std::isnan(older.stage_ends[0].wall));
  {
    H5::H5File f(path, H5F_ACC_RDWR);
    ASSERT_GE(H5Ldelete(f.getId(), "stage_ends", H5P_DEFAULT), 0);  // written before it existed
  }
  const RunRecord q = read_run_file(path);
  EXPECT_TRUE(q.stage_ends.empty());
  EXPECT_FALSE(q.costs.has_value());
  ASSERT_EQ(q.log.size(), 3u);
  EXPECT_TRUE(std::isnan(q.log[2].a_ratio_avg));
  EXPECT_EQ(q.log[2].a_ratio, 1e-4);
  EXPECT_FALSE(q.summary.has_value());
  {
    H5::H5File f(path, H5F_ACC_RDWR);
    H5::Group log = f.openGroup("log");
    h5::write(log, "a_ratio_avg", std::vector<double>{1.0, 2.0});
  }
  try {
    read_run_file(path);
    ADD_FAILURE() << "no error for a short column";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": /log columns of unequal length"),
              std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

// A write that fails midway (here at a file-size limit, which fails write() as a full disk
// does) is an OutputError naming the path; the file written before stays as it was and no
// partial file is left.
TEST(RunFile, FailedWriteKeepsThePreviousFile) {
  RunRecord r;
  r.mesh = crumple::testing::grid_mesh(12, 12, 0.1, 0.1, 0.0, 1);
  r.costs = RunCosts{0.5, 0.75, 3, 1.0};
  const std::string path = crumple::testing::scratch_path("fsize.h5").string();
  write_run_file_atomic(path, r);
  const auto size_before = std::filesystem::file_size(path);
  State s;
  s.x = r.mesh.ref_flat();
  s.v = VecX::Zero(s.x.size());
  s.p = VecX::Zero(r.mesh.num_hinges());
  for (int k = 0; k < 40; ++k) r.frames.push_back({s, "x", 1, k});
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = old;
  small.rlim_cur = size_before + 4096;  // the bigger record cannot fit
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    write_run_file_atomic(path, r);
  } catch (const OutputError& e) {
    message = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_NE(message.find(path + ".new: cannot write the run file"), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(path + ".new"));
  ASSERT_EQ(std::filesystem::file_size(path), size_before);
  const RunRecord q = read_run_file(path);
  EXPECT_TRUE(q.frames.empty());
  std::filesystem::remove(path);
  EXPECT_THROW(write_run_file("no/such/dir/run.h5", r), OutputError);
}

TEST(RunFile, UnreadableFileIsBadInput) {
  EXPECT_THROW(read_run_file("no/such/run.h5"), InputError);
  EXPECT_THROW(read_run_file("README.md"), InputError);
}
