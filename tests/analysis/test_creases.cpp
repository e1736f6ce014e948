// Crease selection and length on a small mesh built in the test, and the run reader on a file
// written with the HDF5 C++ API.
#include "analysis/creases/crease_edges.hpp"
#include "analysis/io/run_reader.hpp"
#include "analysis/run/config_params.hpp"
#include "tests/analysis/synthetic_run.hpp"
#include "tests/support/scratch.hpp"

#include <gtest/gtest.h>

#include <filesystem>
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
  EXPECT_EQ(compaction_from_config(r.config_yaml), 0.27);
  std::filesystem::remove(path);
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
