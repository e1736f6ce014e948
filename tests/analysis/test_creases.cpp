// Crease selection and length on a small mesh built in the test, and the run reader on a file
// written with the HDF5 C++ API.
#include "analysis/creases/crease_edges.hpp"
#include "analysis/io/run_reader.hpp"
#include "analysis/run/compaction.hpp"
#include "analysis/run/config_params.hpp"
#include "tests/analysis/synthetic_run.hpp"
#include "tests/support/scratch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

using namespace crumple::analysis;

TEST(Creases, LengthIsSumOfChosenRestLengths) {
  const MeshData m = synth::square_grid_mesh(8, 0.1);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> small(-0.04, 0.04), big(0.2, 1.5);
  std::bernoulli_distribution pick(0.3);
  std::vector<double> p(m.hinges.size());
  double expected = 0;
  for (std::size_t h = 0; h < p.size(); ++h) {
    if (pick(rng)) {
      p[h] = (h % 2 ? 1 : -1) * big(rng);
      expected += m.rest_lengths[static_cast<std::size_t>(m.hinge_edge[h])];
    } else {
      p[h] = small(rng);
    }
  }
  const auto c = crease_hinges(p, 0.05);
  EXPECT_NEAR(crease_length(m, c), expected, 1e-12);
  // A straight fold across the sheet has the sheet's side as its length.
  std::vector<double> q(m.hinges.size(), 0.0);
  for (auto h : synth::hinges_on_line(m, 0, 0.05)) q[h] = 0.8;
  EXPECT_NEAR(crease_length(m, crease_hinges(q, 0.05)), 0.1, 1e-12);
  const auto fresh = new_creases(crease_hinges(p, 0.05), crease_hinges(q, 0.05));
  for (std::size_t h = 0; h < p.size(); ++h) EXPECT_EQ(fresh[h], c[h] && !(q[h] > 0.05));
}

// The plastic rotation of a fold is its angle times its length however many hinge rows carry
// it; the crease length counts only rows above the threshold. A 60 degree fold across the sheet
// on one row of hinges, then spread over three rows of 20 degrees: the same rotation, no crease
// at a 30 degree threshold.
TEST(Creases, PlasticRotationDoesNotDependOnHowManyRowsCarryAFold) {
  const MeshData m = synth::square_grid_mesh(8, 0.1);
  const double dx = 0.1 / 8, A = M_PI / 3, threshold = 2 * std::sin(M_PI / 12);
  auto c_of = [](double angle) { return 2 * std::sin(angle / 2); };
  std::vector<double> one(m.hinges.size(), 0.0), three(m.hinges.size(), 0.0);
  for (auto h : synth::hinges_on_line(m, 0, 3 * dx)) one[h] = -c_of(A);
  for (int k : {2, 3, 4})
    for (auto h : synth::hinges_on_line(m, 0, k * dx)) three[h] = c_of(A / 3);
  EXPECT_NEAR(plastic_rotation(m, one), A * 0.1, 1e-12);
  EXPECT_NEAR(plastic_rotation(m, three), A * 0.1, 1e-12);
  EXPECT_NEAR(crease_length(m, crease_hinges(one, threshold)), 0.1, 1e-12);
  EXPECT_EQ(crease_length(m, crease_hinges(three, threshold)), 0.0);
  // Restricted to the creased hinges: all of the single row's, none of the spread fold's.
  const auto c1 = crease_hinges(one, threshold), c3 = crease_hinges(three, threshold);
  EXPECT_NEAR(plastic_rotation(m, one, &c1), A * 0.1, 1e-12);
  EXPECT_EQ(plastic_rotation(m, three, &c3), 0.0);
  // |p| beyond 2 (c = 2 sin(theta/2) of a complete fold) counts as a complete fold, pi.
  std::vector<double> over(m.hinges.size(), 0.0);
  for (auto h : synth::hinges_on_line(m, 0, 3 * dx)) over[h] = 2.5;
  EXPECT_NEAR(plastic_rotation(m, over), M_PI * 0.1, 1e-12);
  EXPECT_THROW(plastic_rotation(m, std::vector<double>(3, 0.0)), std::invalid_argument);
}

TEST(RunReader, ReadsWhatWasWritten) {
  const MeshData m = synth::square_grid_mesh(4, 2.0);
  const auto path = crumple::testing::scratch_path("test_reader.h5");
  std::vector<double> p(m.hinges.size(), 0.25);
  synth::write_run(path.string(), m, {p, p});
  const RunData r = read_run(path.string());
  EXPECT_EQ(r.cycles.size(), 2u);
  EXPECT_EQ(r.cycles[1].cycle, 2);
  EXPECT_EQ(r.mesh.hinges, m.hinges);
  EXPECT_EQ(r.mesh.rest_lengths, m.rest_lengths);
  EXPECT_EQ(r.meta["program_version"], "test");
  for (const auto& c : r.cycles) EXPECT_FALSE(c.compaction_recorded);  // none written
  std::filesystem::remove(path);
}

// /cycles/NNNN@compaction: read per cycle (NaN: recorded as "no compacting stage"); the run's D
// for c1, c2 only when every cycle gives the same value, otherwise unset with the reason.
TEST(RunReader, CompactionPerCycle) {
  const MeshData m = synth::square_grid_mesh(4, 2.0);
  const auto path = (std::filesystem::temp_directory_path() / "crumple_test_compaction.h5").string();
  const std::vector<double> p(m.hinges.size(), 0.25);
  auto read_with = [&](std::vector<double> d, std::size_t cycles = 3) {
    synth::WriteOptions o;
    o.cycle_compaction = std::move(d);
    synth::write_run(path, m, std::vector<std::vector<double>>(cycles, p), o);
    return read_run(path);
  };
  RunData r = read_with({0.3, 0.3, 0.3});
  ASSERT_EQ(r.cycles.size(), 3u);
  for (const auto& c : r.cycles) {
    EXPECT_TRUE(c.compaction_recorded);
    EXPECT_EQ(c.compaction, 0.3);
  }
  RunCompaction k = run_compaction(r.cycles);
  EXPECT_EQ(k.value, 0.3);
  EXPECT_TRUE(k.note.empty());

  r = read_with({0.3, 0.3, 0.18});  // a protocol whose compaction changes between cycles
  EXPECT_EQ(r.cycles[2].compaction, 0.18);
  k = run_compaction(r.cycles);
  EXPECT_FALSE(k.value.has_value());
  EXPECT_NE(k.note.find("differs from cycle to cycle"), std::string::npos) << k.note;
  EXPECT_NE(k.note.find("0.3 in cycle(s) 1-2"), std::string::npos) << k.note;
  EXPECT_NE(k.note.find("0.18 in cycle(s) 3"), std::string::npos) << k.note;

  r = read_with({0.3, NAN, 0.3});  // cycle 2 has no compacting stage
  EXPECT_TRUE(r.cycles[1].compaction_recorded);
  EXPECT_FALSE(r.cycles[1].compaction.has_value());
  k = run_compaction(r.cycles);
  EXPECT_FALSE(k.value.has_value());
  EXPECT_NE(k.note.find("no stage of cycle(s) 2 compacts"), std::string::npos) << k.note;

  r = read_with({});  // an older file
  k = run_compaction(r.cycles);
  EXPECT_FALSE(k.value.has_value());
  EXPECT_NE(k.note.find("records no compaction ratio"), std::string::npos) << k.note;

  // A ratio outside (0, 1] is a damaged file, refused naming the attribute.
  for (double bad : {0.0, 1.5, -0.2, std::numeric_limits<double>::infinity()}) {
    try {
      read_with({0.3, bad, 0.3});
      ADD_FAILURE() << "accepted compaction " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("/cycles/0002@compaction"), std::string::npos) << e.what();
    }
  }
  std::filesystem::remove(path);
}

TEST(CompactionNote, CycleRanges) {
  EXPECT_EQ(cycle_ranges({5, 1, 2, 3, 7, 8}), "1-3, 5, 7-8");
  EXPECT_EQ(cycle_ranges({4}), "4");
  EXPECT_EQ(cycle_ranges({}), "");
}

TEST(RunReader, BadInputNamesTheProblem) {
  const MeshData m = synth::square_grid_mesh(4, 2.0);
  const auto path = (std::filesystem::temp_directory_path() / "crumple_test_bad.h5").string();
  std::vector<double> p(m.hinges.size(), 0.25);
  auto expect_error = [&](const std::string& needle) {
    try {
      read_run(path);
      ADD_FAILURE() << "no error for " << needle;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  };
  synth::WriteOptions o;
  o.with_cycles_group = false;
  synth::write_run(path, m, {p}, o);
  expect_error("/cycles");
  synth::write_run(path, m, {}, {});
  expect_error("/cycles");
  o = {};
  o.wrong_p_shape = true;
  synth::write_run(path, m, {p}, o);
  expect_error("/cycles/0001/p");
  o = {};
  o.omit_rest_lengths = true;
  synth::write_run(path, m, {p}, o);
  expect_error("/mesh/rest_lengths");
  std::filesystem::remove(path);
  expect_error("no such file");
}
