// End-to-end: crumple-analyze on small synthetic run files (layout of docs/FILE_FORMAT.md),
// and bad input giving exit code 2 with nothing written.
#include "tests/analysis/synthetic_run.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sys/wait.h>

namespace fs = std::filesystem;
using namespace crumple::analysis;

namespace {

int run_analyze(const std::string& args) {
  const std::string cmd = std::string(CRUMPLE_ANALYZE_EXE) + " " + args + " > /dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("crumple_test_cli_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST(CrumpleAnalyze, SyntheticRunEndToEnd) {
  const fs::path dir = scratch("e2e");
  const MeshData m = synth::square_grid_mesh(20, 0.1);  // 5 mm triangles on a 10 cm sheet
  std::vector<std::vector<double>> cycles;
  std::vector<double> p(m.hinges.size(), 0.0);
  for (std::size_t h = 0; h < p.size(); ++h) p[h] = 0.01 * std::sin(1.0 * h);  // sub-threshold
  auto crease = [&](int axis, double c, double value) {
    for (auto h : synth::hinges_on_line(m, axis, c)) p[h] = value;
  };
  crease(0, 0.05, 1.2);
  cycles.push_back(p);
  crease(1, 0.05, -0.9);
  cycles.push_back(p);
  crease(0, 0.025, 0.4);
  cycles.push_back(p);
  cycles.push_back(p);  // a cycle that adds nothing
  const fs::path run = dir / "run.h5";
  synth::write_run(run.string(), m, cycles);

  ASSERT_EQ(run_analyze(run.string()), 0);
  const fs::path out = dir / "run.analysis";
  for (const char* f : {"stats.json", "cycles.csv", "facets.csv", "distribution.csv",
                        "crease_0001.png", "facets_0004.png"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  std::ifstream in(out / "stats.json");
  const auto j = nlohmann::json::parse(in);
  const auto& c = j["cycles"];
  ASSERT_EQ(c.size(), 4u);
  const double length[] = {0.1, 0.2, 0.3, 0.3}, fresh[] = {0.1, 0.1, 0.1, 0.0};
  const int facets[] = {2, 4, 6, 6};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(c[i]["crease_length_m"].get<double>(), length[i], 1e-12) << i;
    EXPECT_NEAR(c[i]["crease_length_L0"].get<double>(), length[i] / 0.1, 1e-9) << i;
    EXPECT_NEAR(c[i]["new_crease_length_m"].get<double>(), fresh[i], 1e-12) << i;
    EXPECT_EQ(c[i]["n_facets"].get<int>(), facets[i]) << i;
    EXPECT_NEAR(c[i]["perimeter_P"].get<double>(), length[i] / 0.1, 0.05 * length[i] / 0.1) << i;
  }
  EXPECT_NEAR(j["sheet"]["L0_m"].get<double>(), 0.1, 1e-12);
  EXPECT_NEAR(j["sheet"]["area_m2"].get<double>(), 0.01, 1e-12);
  EXPECT_NEAR(j["input"]["compaction"].get<double>(), 0.27, 1e-12);
  EXPECT_TRUE(j["log_fit"]["crease_length_L0"].contains("c1"));
  EXPECT_TRUE(c[2].contains("a_fit") && c[2].contains("ks_pvalue"));

  // Facet areas of the last cycle: columns of 1/4, 1/4, 1/2 of the width times two rows.
  std::ifstream fcsv(out / "facets.csv");
  std::string line;
  std::getline(fcsv, line);
  std::vector<double> x;
  double sum = 0;
  while (std::getline(fcsv, line)) {
    if (line.rfind("4,", 0) != 0) continue;
    std::stringstream ss(line);
    std::string cell;
    std::vector<std::string> cols;
    while (std::getline(ss, cell, ',')) cols.push_back(cell);
    x.push_back(std::stod(cols[3]));
    sum += std::stod(cols[2]);
  }
  std::sort(x.begin(), x.end());
  const double truth[] = {0.125, 0.125, 0.125, 0.125, 0.25, 0.25};
  ASSERT_EQ(x.size(), 6u);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(x[i] / truth[i], 1.0, 0.02) << i;
  EXPECT_NEAR(sum, 0.01, 1e-9);  // the facets tile the sheet (CSV has 10 digits)
  fs::remove_all(dir);
}

TEST(CrumpleAnalyze, BadInputExitsTwoAndWritesNothing) {
  const fs::path dir = scratch("bad");
  const MeshData m = synth::square_grid_mesh(4, 0.1);
  const std::vector<double> p(m.hinges.size(), 0.3);
  auto check = [&](const fs::path& file, const std::string& what) {
    const fs::path out = dir / "out";
    EXPECT_EQ(run_analyze(file.string() + " -o " + out.string()), 2) << what;
    EXPECT_FALSE(fs::exists(out)) << what;
  };
  check(dir / "missing.h5", "missing file");
  std::ofstream(dir / "text.h5") << "not hdf5\n";
  check(dir / "text.h5", "not HDF5");
  synth::WriteOptions o;
  o.with_cycles_group = false;
  synth::write_run((dir / "nocycles.h5").string(), m, {p}, o);
  check(dir / "nocycles.h5", "no /cycles");
  synth::write_run((dir / "empty.h5").string(), m, {}, {});
  check(dir / "empty.h5", "empty /cycles");
  o = {};
  o.wrong_p_shape = true;
  synth::write_run((dir / "shape.h5").string(), m, {p}, o);
  check(dir / "shape.h5", "wrong shape");
  synth::write_run((dir / "good.h5").string(), m, {p});
  EXPECT_EQ(run_analyze((dir / "good.h5").string() + " --threshold -1"), 2) << "bad argument";
  fs::remove_all(dir);
}
