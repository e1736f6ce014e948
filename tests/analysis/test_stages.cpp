// Per-stage crease accounting: the stages' new lengths add up to the cycle's new length (also
// when hinges fall below the threshold and come back), the share after compress, the reader of
// /stage_ends, and a file without /stage_ends read with a warning.
#include "analysis/creases/crease_edges.hpp"
#include "analysis/creases/stage_accounting.hpp"
#include "analysis/io/run_reader.hpp"
#include "analysis/run/analyze_run.hpp"
#include "tests/analysis/synthetic_run.hpp"
#include "tests/support/scratch.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

using namespace crumple::analysis;

namespace {

const char* const kStages[] = {"roll", "compress", "release", "unfold"};

double edge_length(const MeshData& m, std::size_t h) {
  return m.rest_lengths[static_cast<std::size_t>(m.hinge_edge[h])];
}

/// A run in memory: `cycles` cycles of four stages each on a grid mesh, with random plastic
/// fields that mostly grow but also flicker: some hinges drop below the threshold at a stage
/// end and come back later, some creased at a cycle's end are lost at the next roll. The last
/// stage end of each cycle is the cycle's field.
RunData flickering_run(int cycles, unsigned seed) {
  RunData run;
  run.path = "memory";
  run.mesh = synth::square_grid_mesh(12, 0.1);
  run.has_stage_ends = true;
  run.config_yaml = "integrator:\n  plastic_c0: 0.2\nprotocol:\n  stages:\n    - type: compress\n"
                    "      compaction: 0.3\n";
  const std::size_t h = run.mesh.hinges.size();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> p(h, 0.0);
  double t = 0;
  for (int c = 1; c <= cycles; ++c) {
    for (int k = 0; k < 4; ++k) {
      for (std::size_t i = 0; i < h; ++i) {
        const double r = u(rng);
        if (r < 0.04 * (k == 1 ? 3 : 1))
          p[i] = (i % 2 ? 1 : -1) * (0.2 + u(rng));  // creased (most in compress)
        else if (r < 0.07 && std::abs(p[i]) > 0.1)
          p[i] = p[i] > 0 ? 0.05 : -0.05;  // falls back below the threshold
      }
      StageEndData s;
      s.cycle = c;
      s.stage_index = k;
      s.stage = kStages[k];
      s.t = (t += 0.25);
      s.p = p;
      run.stage_ends.push_back(s);
    }
    run.cycles.push_back({c, p});
  }
  return run;
}

}  // namespace

TEST(StageAccounting, NewLengthsAddUpToTheCycleWithFlicker) {
  const RunData run = flickering_run(4, 3);
  const double thr = 0.1;
  std::vector<char> before;
  int flicker = 0;
  for (const auto& c : run.cycles) {
    std::vector<const StageEndData*> st;
    for (const auto& s : run.stage_ends)
      if (s.cycle == c.cycle) st.push_back(&s);
    const auto now = crease_hinges(c.p, thr);
    const auto acc = account_stages(run.mesh, st, now, before, thr);
    ASSERT_EQ(acc.size(), 4u);
    const double cycle_new = crease_length(run.mesh, new_creases(now, before));
    double sum = 0, lost = 0;
    for (const auto& s : acc) sum += s.new_length, lost += s.lost_length;
    EXPECT_NEAR(sum, cycle_new, 1e-12 * cycle_new) << "cycle " << c.cycle;
    // The cumulative length changes by what appears minus what is lost: with flicker the plain
    // difference of successive crease sets would overcount the new length.
    double appeared = 0;
    for (std::size_t k = 0; k < acc.size(); ++k) {
      const auto& prev = k == 0 ? before : crease_hinges(st[k - 1]->p, thr);
      const auto cur = crease_hinges(st[k]->p, thr);
      appeared += crease_length(run.mesh, new_creases(cur, prev));
      EXPECT_NEAR(acc[k].crease_length, crease_length(run.mesh, cur), 1e-12);
      EXPECT_EQ(acc[k].index, static_cast<int>(k));
      EXPECT_EQ(acc[k].stage, kStages[k]);
    }
    flicker += appeared > cycle_new + 1e-12;
    EXPECT_GT(lost, 0.0) << "the test run should lose creases in every cycle";
    before = now;
  }
  EXPECT_GT(flicker, 0) << "the test run should have hinges that come back";
}

TEST(StageAccounting, AttributionAndShareAfterCompress) {
  // Four hinges of known edges on a 2 x 2 grid; stage ends roll, compress, release, unfold.
  const MeshData m = synth::square_grid_mesh(2, 1.0);
  const std::size_t h = m.hinges.size();
  ASSERT_GE(h, 4u);
  auto field = [&](std::initializer_list<std::size_t> creased) {
    std::vector<double> p(h, 0.0);
    for (auto i : creased) p[i] = 0.5;
    return p;
  };
  // hinge 0: creased in compress and stays; hinge 1: creased in roll, lost in compress, back in
  // unfold (counts at unfold); hinge 2: creased in release; hinge 3: creased before the cycle.
  std::vector<StageEndData> se = {{1, 0, "roll", 1, field({1, 3})},
                                  {1, 1, "compress", 2, field({0, 3})},
                                  {1, 2, "release", 3, field({0, 2, 3})},
                                  {1, 3, "unfold", 4, field({0, 1, 2, 3})}};
  std::vector<const StageEndData*> st;
  for (const auto& s : se) st.push_back(&s);
  const auto before = crease_hinges(field({3}), 0.1);
  const auto now = crease_hinges(se.back().p, 0.1);
  const auto acc = account_stages(m, st, now, before, 0.1);
  EXPECT_DOUBLE_EQ(acc[0].new_length, 0.0);
  EXPECT_DOUBLE_EQ(acc[1].new_length, edge_length(m, 0));
  EXPECT_DOUBLE_EQ(acc[2].new_length, edge_length(m, 2));
  EXPECT_DOUBLE_EQ(acc[3].new_length, edge_length(m, 1));
  EXPECT_DOUBLE_EQ(acc[1].lost_length, edge_length(m, 1));
  EXPECT_EQ(acc[3].crease_edges, 4);
  const double total = edge_length(m, 0) + edge_length(m, 1) + edge_length(m, 2);
  const auto share = share_after_last(acc, "compress", total);
  ASSERT_TRUE(share.has_value());
  EXPECT_NEAR(*share, (edge_length(m, 1) + edge_length(m, 2)) / total, 1e-15);
  EXPECT_FALSE(share_after_last(acc, "press", total).has_value());  // no such stage
  EXPECT_FALSE(share_after_last(acc, "compress", 0.0).has_value());  // nothing new
  EXPECT_FALSE(share_after_last({}, "compress", total).has_value());  // no stage data
}

TEST(StageAccounting, AnalyzeRunReportsStagesThatAddUp) {
  const RunData run = flickering_run(3, 8);
  AnalyzeOptions opt;
  opt.bootstrap = 10;
  opt.threshold = 0.1;
  const RunAnalysis res = analyze_run(run, opt);
  ASSERT_EQ(res.cycles.size(), 3u);
  for (const auto& c : res.cycles) {
    ASSERT_EQ(c.stages.size(), 4u);
    double sum = 0;
    for (const auto& s : c.stages) sum += s.new_length;
    EXPECT_NEAR(sum, c.new_crease_length_L0, 1e-12) << c.cycle;
    EXPECT_NEAR(c.stages.back().crease_length, c.crease_length_L0, 1e-12) << c.cycle;
    ASSERT_TRUE(c.new_length_share_after_compress.has_value());
    EXPECT_NEAR(*c.new_length_share_after_compress,
                (c.stages[2].new_length + c.stages[3].new_length) / c.new_crease_length_L0,
                1e-12);
  }
  for (const auto& w : res.warnings) EXPECT_EQ(w.find("add up"), std::string::npos) << w;
}

TEST(RunReader, ReadsStageEnds) {
  const MeshData m = synth::square_grid_mesh(4, 0.1);
  const auto path = crumple::testing::scratch_path("test_stages.h5").string();
  std::vector<double> p(m.hinges.size(), 0.0);
  synth::WriteOptions o;
  for (int c = 1; c <= 2; ++c)
    for (int k = 0; k < 4; ++k) {
      p[static_cast<std::size_t>(4 * (c - 1) + k)] = 0.4;
      o.stage_ends.push_back({c, k, kStages[k], 0.5 * (4 * (c - 1) + k + 1), p});
    }
  synth::write_run(path, m, {o.stage_ends[3].p, o.stage_ends[7].p}, o);
  const RunData r = read_run(path);
  EXPECT_TRUE(r.has_stage_ends);
  ASSERT_EQ(r.stage_ends.size(), 8u);
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_EQ(r.stage_ends[k].cycle, o.stage_ends[k].cycle);
    EXPECT_EQ(r.stage_ends[k].stage_index, o.stage_ends[k].stage_index);
    EXPECT_EQ(r.stage_ends[k].stage, o.stage_ends[k].stage);
    EXPECT_DOUBLE_EQ(r.stage_ends[k].t, o.stage_ends[k].t);
    EXPECT_EQ(r.stage_ends[k].p, o.stage_ends[k].p);
  }
  for (const auto& w : r.warnings) EXPECT_EQ(w.find("stage_ends"), std::string::npos) << w;

  o.stage_end_without_cycle_attr = true;  // malformed record: an error naming it
  synth::write_run(path, m, {p}, o);
  try {
    read_run(path);
    ADD_FAILURE() << "no error for a stage end without @cycle";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/stage_ends/000000@cycle"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove(path);
}

TEST(RunReader, OldFileWithoutStageEndsWarns) {
  const MeshData m = synth::square_grid_mesh(4, 0.1);
  const auto path = crumple::testing::scratch_path("test_old.h5").string();
  synth::write_run(path, m, {std::vector<double>(m.hinges.size(), 0.3)});
  const RunData r = read_run(path);
  EXPECT_FALSE(r.has_stage_ends);
  EXPECT_TRUE(r.stage_ends.empty());
  bool warned = false;
  for (const auto& w : r.warnings) warned = warned || w.find("/stage_ends") != std::string::npos;
  EXPECT_TRUE(warned);
  AnalyzeOptions opt;
  opt.bootstrap = 10;
  const RunAnalysis res = analyze_run(r, opt);
  ASSERT_EQ(res.cycles.size(), 1u);
  EXPECT_TRUE(res.cycles[0].stages.empty());
  EXPECT_FALSE(res.cycles[0].new_length_share_after_compress.has_value());
  std::filesystem::remove(path);
}
