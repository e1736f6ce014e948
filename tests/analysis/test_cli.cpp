// End-to-end: crumple-analyze on small synthetic run files (layout of docs/FILE_FORMAT.md): an
// older file without /stage_ends (works, with a warning), a file with /stage_ends and c0 in its
// config (per-stage lengths, threshold rule, sensitivity table, increment fits, the new CSVs),
// and bad input giving exit code 2 with nothing written.
#include "crumple/version.hpp"
#include "tests/analysis/synthetic_run.hpp"
#include "tests/support/command_output.hpp"
#include "tests/support/scratch.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace fs = std::filesystem;
using namespace crumple::analysis;

namespace {

int run_analyze(const std::string& args) {
  const std::string cmd = std::string(CRUMPLE_ANALYZE_EXE) + " " + args + " > /dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<std::string> lines(const fs::path& f) {
  std::ifstream in(f);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

fs::path scratch(const std::string& name) {
  const fs::path d = crumple::testing::scratch_path("test_cli_" + name);
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
  synth::WriteOptions o;
  const double D = 0.36;  // recorded for every cycle, as crumple-sim does
  o.cycle_compaction.assign(cycles.size(), D);
  synth::write_run(run.string(), m, cycles, o);

  ASSERT_EQ(run_analyze(run.string()), 0);
  const fs::path out = dir / "run.analysis";
  for (const char* f : {"stats.json", "cycles.csv", "facets.csv", "distribution.csv",
                        "crease_0001.png", "facets_0004.png"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  std::ifstream in(out / "stats.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["analysis"]["program_version"], crumple::kVersion);  // the analyser's provenance
  EXPECT_EQ(j["analysis"]["git_revision"], crumple::kGitRevision);
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
  // The compaction comes from the cycles' records, not from the config (which says 0.27).
  EXPECT_EQ(j["input"]["compaction"].get<double>(), D);
  EXPECT_TRUE(j["input"]["compaction_note"].is_null());
  for (const auto& ci : c) EXPECT_EQ(ci["compaction"].get<double>(), D);
  const auto& fit = j["log_fit"]["crease_length_L0"];
  ASSERT_TRUE(fit.contains("c1"));
  EXPECT_NEAR(fit["c1"].get<double>(), fit["C"].get<double>() / (1 - D), 1e-12);
  EXPECT_NEAR(fit["c2"].get<double>(), D / fit["n0"].get<double>(), 1e-12);
  const auto csv = lines(out / "cycles.csv");
  const auto column = [](const std::string& row, std::size_t k) {
    std::stringstream ss(row);
    std::string cell;
    for (std::size_t i = 0; i <= k; ++i) std::getline(ss, cell, ',');
    return cell;
  };
  std::size_t k_comp = 0;
  while (column(csv[0], k_comp) != "compaction" && k_comp < 100) ++k_comp;
  ASSERT_LT(k_comp, 100u) << csv[0];
  EXPECT_EQ(std::stod(column(csv[1], k_comp)), D);
  EXPECT_EQ(csv[0].substr(csv[0].rfind(',') + 1), "fit_above_floor_edge");
  EXPECT_TRUE(c[2].contains("a_fit") && c[2].contains("ks_pvalue"));
  // An older file: no /stage_ends, so no per-stage data, said in a warning; no c0 in the
  // config, so the default c0 with a warning.
  bool stage_warning = false, c0_warning = false;
  for (const auto& w : j["warnings"]) {
    stage_warning = stage_warning || w.get<std::string>().find("/stage_ends") != std::string::npos;
    c0_warning = c0_warning || w.get<std::string>().find("plastic_c0") != std::string::npos;
  }
  EXPECT_TRUE(stage_warning);
  EXPECT_TRUE(c0_warning);
  for (const auto& ci : c) {
    EXPECT_TRUE(ci["stages"].is_array() && ci["stages"].empty());
    EXPECT_TRUE(ci["new_length_share_after_compress"].is_null());
  }
  EXPECT_EQ(j["parameters"]["threshold_rule"]["kind"], "fraction_of_c0");
  EXPECT_EQ(j["parameters"]["threshold_rule"]["c0"], 0.1);
  EXPECT_EQ(lines(out / "stages.csv").size(), 1u);  // the header only

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

TEST(CrumpleAnalyze, StagesThresholdRuleAndSensitivity) {
  const fs::path dir = scratch("stages");
  const MeshData m = synth::square_grid_mesh(20, 0.1);
  const char* names[] = {"roll", "compress", "release", "unfold"};
  synth::WriteOptions o;
  o.config = "integrator:\n  plastic_c0: 0.3\nprotocol:\n  stages:\n    - type: roll\n"
             "    - type: compress\n      compaction: 0.27\n    - type: release\n"
             "    - type: unfold\n";
  std::vector<std::vector<double>> cycles;
  std::vector<double> p(m.hinges.size(), 0.0);
  // Cycle n creases the line x = n cm in compress (|p| = 0.9) and y = n cm in release
  // (|p| = 0.2: a crease at 0.5 c0 = 0.15, not at c0 = 0.3).
  double t = 0;
  for (int n = 1; n <= 4; ++n) {
    for (int k = 0; k < 4; ++k) {
      if (k == 1)
        for (auto h : synth::hinges_on_line(m, 0, 0.01 * n)) p[h] = 0.9;
      if (k == 2)
        for (auto h : synth::hinges_on_line(m, 1, 0.01 * n)) p[h] = -0.2;
      o.stage_ends.push_back({n, k, names[k], t += 0.5, p});
    }
    cycles.push_back(p);
  }
  const fs::path run = dir / "run.h5";
  synth::write_run(run.string(), m, cycles, o);
  ASSERT_EQ(run_analyze(run.string() + " --bootstrap 20"), 0);
  const fs::path out = dir / "run.analysis";
  std::ifstream in(out / "stats.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_DOUBLE_EQ(j["parameters"]["threshold"].get<double>(), 0.15);
  EXPECT_EQ(j["parameters"]["threshold_rule"]["kind"], "fraction_of_c0");
  EXPECT_DOUBLE_EQ(j["parameters"]["threshold_rule"]["factor"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(j["parameters"]["threshold_rule"]["c0"].get<double>(), 0.3);
  EXPECT_TRUE(j["parameters"]["threshold_note"].is_string());
  const auto& c = j["cycles"];
  ASSERT_EQ(c.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    const auto& st = c[i]["stages"];
    ASSERT_EQ(st.size(), 4u) << i;
    double sum = 0;
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(st[k]["index"], k);
      EXPECT_EQ(st[k]["stage"], names[k]);
      sum += st[k]["new_crease_length_L0"].get<double>();
    }
    EXPECT_NEAR(sum, c[i]["new_crease_length_L0"].get<double>(), 1e-12) << i;
    EXPECT_NEAR(st[1]["new_crease_length_L0"].get<double>(), 1.0, 1e-9) << i;  // x line
    EXPECT_NEAR(st[2]["new_crease_length_L0"].get<double>(), 1.0, 1e-9) << i;  // y line
    EXPECT_NEAR(c[i]["new_length_share_after_compress"].get<double>(), 0.5, 1e-9) << i;
    EXPECT_NEAR(st[3]["crease_length_L0"].get<double>(), 2.0 * (i + 1), 1e-9) << i;
    EXPECT_TRUE(c[i]["dangling_fraction"].is_number());
    // i + 1 lines folded by 2 asin(0.45) and as many by 2 asin(0.1), each across the sheet;
    // all of them creased.
    EXPECT_NEAR(c[i]["plastic_rotation_L0"].get<double>(),
                2.0 * (i + 1) * (std::asin(0.45) + std::asin(0.1)), 1e-9) << i;
    EXPECT_NEAR(c[i]["creased_rotation_share"].get<double>(), 1.0, 1e-12) << i;
    // The 20 x 20 grid's interior hinges: 19 lines across in x and in y, and one diagonal of
    // sqrt(2) / 20 L0 in each of the 400 cells.
    const double network = 38.0 + 20.0 * std::sqrt(2.0);
    EXPECT_NEAR(j["sheet"]["hinge_length_L0"].get<double>(), network, 1e-9);
    EXPECT_NEAR(c[i]["creased_hinge_share"].get<double>(),
                c[i]["crease_length_L0"].get<double>() / network, 1e-12) << i;
    EXPECT_TRUE(c[i]["n_single_triangle_facets"].is_number_integer());
    EXPECT_TRUE(c[i]["single_triangle_fraction"].is_number());
  }
  const auto& s = j["threshold_sensitivity"];
  ASSERT_EQ(s["factors_of_c0"].size(), 6u);
  ASSERT_EQ(s["cycles"].size(), 4u);
  // At F <= 0.5 both lines count, at F >= 0.75 (threshold 0.225 > 0.2) only the x lines.
  const auto& l4 = s["cycles"][3]["crease_length_L0"];
  EXPECT_NEAR(l4[1].get<double>(), 8.0, 1e-9);
  EXPECT_NEAR(l4[2].get<double>(), 4.0, 1e-9);
  EXPECT_EQ(s["cycles"][3]["n_facets"][1], 25);
  EXPECT_EQ(s["cycles"][3]["n_facets"][2], 5);
  for (const char* k : {"crease_length_L0", "perimeter_P", "crease_length_L0_increments",
                        "perimeter_P_increments"}) {
    ASSERT_TRUE(j["log_fit"][k].is_object()) << k;
    EXPECT_TRUE(j["log_fit"][k].contains("sigma_C") && j["log_fit"][k].contains("sigma_n0")) << k;
  }
  EXPECT_NE(j["log_fit"]["perimeter_P_increments"]["model"].get<std::string>().find("increments"),
            std::string::npos);
  // A file without /cycles/NNNN@compaction (before it was recorded) is analysed all the same,
  // without c1, c2, and says why: the compress stage's compaction in its config is not used.
  EXPECT_TRUE(j["input"]["compaction"].is_null());
  EXPECT_NE(j["input"]["compaction_note"].get<std::string>().find("records no compaction"),
            std::string::npos);
  EXPECT_EQ(j["log_fit"]["compaction_note"], j["input"]["compaction_note"]);
  EXPECT_FALSE(j["log_fit"]["perimeter_P_increments"].contains("c1"));
  for (const auto& ci : c) EXPECT_TRUE(ci["compaction"].is_null());

  const auto stages_csv = lines(out / "stages.csv");
  ASSERT_EQ(stages_csv.size(), 1u + 16u);
  EXPECT_EQ(stages_csv[0], "cycle,stage_index,stage,t,crease_edges,crease_length_L0,"
                           "new_crease_length_L0");
  EXPECT_EQ(stages_csv[2].rfind("1,1,compress,", 0), 0u) << stages_csv[2];
  const auto sens_csv = lines(out / "sensitivity.csv");
  ASSERT_EQ(sens_csv.size(), 1u + 4u * 6u);
  EXPECT_EQ(sens_csv[0], "cycle,factor_of_c0,threshold,crease_length_L0,perimeter_P,n_facets");

  // --threshold-c0 1 moves the threshold to c0: the release creases (0.2) no longer count.
  ASSERT_EQ(run_analyze(run.string() + " --bootstrap 20 --threshold-c0 1 -o " +
                        (dir / "c0").string()), 0);
  std::ifstream in2(dir / "c0" / "stats.json");
  const auto j2 = nlohmann::json::parse(in2);
  EXPECT_DOUBLE_EQ(j2["parameters"]["threshold"].get<double>(), 0.3);
  EXPECT_NEAR(j2["cycles"][3]["crease_length_L0"].get<double>(), 4.0, 1e-9);
  EXPECT_NEAR(j2["cycles"][3]["new_length_share_after_compress"].get<double>(), 0.0, 1e-12);
  fs::remove_all(dir);
}

TEST(CrumpleAnalyze, ThresholdAndThresholdC0TogetherExitTwo) {
  const fs::path dir = scratch("both");
  const MeshData m = synth::square_grid_mesh(4, 0.1);
  synth::write_run((dir / "good.h5").string(), m, {std::vector<double>(m.hinges.size(), 0.3)});
  const fs::path out = dir / "out";
  const std::string base = (dir / "good.h5").string() + " -o " + out.string();
  EXPECT_EQ(run_analyze(base + " --threshold 0.1 --threshold-c0 0.5"), 2);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(run_analyze(base + " --threshold-c0 0"), 2);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(run_analyze(base + " --threshold 0.1"), 0);
  std::ifstream in(out / "stats.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["parameters"]["threshold_rule"]["kind"], "absolute");
  EXPECT_DOUBLE_EQ(j["parameters"]["threshold"].get<double>(), 0.1);
  fs::remove_all(dir);
}

// --px-per-edge sets the raster from the mesh: the mean edge (of an equilateral triangle of the
// mean triangle area) spans that many pixels, and stats.json records both; with --px-per-cm it
// is refused.
TEST(CrumpleAnalyze, RasterFollowsTheMeshWithPxPerEdge) {
  const fs::path dir = scratch("px_per_edge");
  const MeshData m = synth::square_grid_mesh(4, 0.1);  // 32 triangles of 0.1^2/32 m^2
  synth::write_run((dir / "good.h5").string(), m, {std::vector<double>(m.hinges.size(), 0.3)});
  const fs::path out = dir / "out";
  const std::string base = (dir / "good.h5").string() + " -o " + out.string();
  EXPECT_EQ(run_analyze(base + " --px-per-edge 24 --px-per-cm 40"), 2);
  EXPECT_FALSE(fs::exists(out));
  ASSERT_EQ(run_analyze(base + " --px-per-edge 24"), 0);
  std::ifstream in(out / "stats.json");
  const auto j = nlohmann::json::parse(in);
  const double edge_m = std::sqrt(4.0 * (0.01 / 32) / std::sqrt(3.0));
  EXPECT_NEAR(j["parameters"]["px_per_cm"].get<double>(), 24.0 / (100.0 * edge_m), 1e-9);
  EXPECT_DOUBLE_EQ(j["parameters"]["px_per_edge"].get<double>(), 24.0);
  EXPECT_NEAR(j["sheet"]["px_per_m"].get<double>(), 24.0 / edge_m, 1e-6);
  fs::remove_all(dir);
}

// --close-mm sets the closing kernel in millimetres of the flat sheet: its pixel width follows
// the raster and is recorded beside the millimetres; two crease lines closer than it merge
// into one and the strip between them is no facet; with --close-px it is refused.
TEST(CrumpleAnalyze, ClosingInMillimetresMergesCloseCreases) {
  const fs::path dir = scratch("close_mm");
  const MeshData m = synth::square_grid_mesh(8, 0.1);  // grid lines 12.5 mm apart
  std::vector<double> p(m.hinges.size(), 0.0);
  // Two full-length lines x = 50 and 62.5 mm and one line y = 50 mm: six facets.
  for (double x : {0.05, 0.0625})
    for (auto h : synth::hinges_on_line(m, 0, x)) p[h] = 0.5;
  for (auto h : synth::hinges_on_line(m, 1, 0.05)) p[h] = 0.5;
  synth::write_run((dir / "good.h5").string(), m, {p});
  const std::string run = (dir / "good.h5").string();
  EXPECT_EQ(run_analyze(run + " -o " + (dir / "both").string() + " --close-mm 1 --close-px 3"), 2);
  EXPECT_FALSE(fs::exists(dir / "both"));
  auto stats = [&](const std::string& name, const std::string& args) {
    const fs::path out = dir / name;
    EXPECT_EQ(run_analyze(run + " -o " + out.string() + " --threshold 0.1 --px-per-cm 40 " + args),
              0) << args;
    std::ifstream in(out / "stats.json");
    return nlohmann::json::parse(in);
  };
  const auto facets = [](const nlohmann::json& j) { return j["cycles"][0]["n_facets"].get<int>(); };
  const auto by_px = stats("by_px", "--close-px 3");
  EXPECT_TRUE(by_px["parameters"]["close_mm"].is_null());
  EXPECT_EQ(by_px["parameters"]["close_px"].get<int>(), 3);
  EXPECT_EQ(facets(by_px), 6);
  const auto narrow = stats("narrow", "--close-mm 1");
  EXPECT_EQ(narrow["parameters"]["close_px"].get<int>(), 5);  // 1 mm at 40 px/cm, made odd
  EXPECT_DOUBLE_EQ(narrow["parameters"]["close_mm"].get<double>(), 1.0);
  EXPECT_EQ(facets(narrow), 6);
  const auto wide = stats("wide", "--close-mm 15");
  EXPECT_EQ(wide["parameters"]["close_px"].get<int>(), 61);
  EXPECT_EQ(facets(wide), 4);
  if (::testing::Test::HasFailure()) return;
  fs::remove_all(dir);
}

// --crease-width-mm: three neighbouring rows of 8 degrees each (a 24-degree fold spread over
// grid rows 5 mm apart) are no crease hinge by hinge at 18.3 degrees and a crease across a band
// reaching from each row to the others, closed over the band's width unless --close-mm is given;
// recorded in the parameters; refused beside --close-px.
TEST(CrumpleAnalyze, CreasesSummedAcrossABand) {
  const fs::path dir = scratch("crease_band");
  const MeshData m = synth::square_grid_mesh(20, 0.1);
  std::vector<double> p(m.hinges.size(), 0.0);
  for (double x : {0.045, 0.05, 0.055})
    for (auto h : synth::hinges_on_line(m, 0, x)) p[h] = 2 * std::sin(4.0 * M_PI / 180);
  synth::write_run((dir / "run.h5").string(), m, {p});
  const std::string run = (dir / "run.h5").string();
  EXPECT_EQ(run_analyze(run + " -o " + (dir / "both").string() +
                        " --crease-width-mm 2 --close-px 3"), 2);
  EXPECT_FALSE(fs::exists(dir / "both"));
  auto stats = [&](const std::string& name, const std::string& args) {
    const fs::path out = dir / name;
    EXPECT_EQ(run_analyze(run + " -o " + out.string() + " --crease-angle 18.3 --px-per-cm 40 " +
                          args), 0) << args;
    std::ifstream in(out / "stats.json");
    return nlohmann::json::parse(in);
  };
  const auto single = stats("single", "");
  EXPECT_TRUE(single["parameters"]["crease_width_mm"].is_null());
  EXPECT_EQ(single["cycles"][0]["crease_length_L0"].get<double>(), 0.0);
  const auto band = stats("band", "--crease-width-mm 21");  // reaches 10.5 mm to each side
  EXPECT_DOUBLE_EQ(band["parameters"]["crease_width_mm"].get<double>(), 21.0);
  EXPECT_NEAR(band["cycles"][0]["crease_length_L0"].get<double>(), 3.0, 1e-9);
  EXPECT_EQ(band["parameters"]["close_px"].get<int>(), 85);  // 21 mm at 40 px/cm, made odd
  EXPECT_EQ(band["cycles"][0]["n_facets"].get<int>(), 2);     // the band closed into one crease
  const auto narrow = stats("narrow", "--crease-width-mm 11");  // the outer rows see 16 degrees
  EXPECT_NEAR(narrow["cycles"][0]["crease_length_L0"].get<double>(), 1.0, 1e-9);
  const auto open = stats("open", "--crease-width-mm 21 --close-mm 1");
  EXPECT_EQ(open["parameters"]["close_px"].get<int>(), 5);
  EXPECT_EQ(open["cycles"][0]["n_facets"].get<int>(), 4);     // three lines drawn apart
  if (::testing::Test::HasFailure()) return;
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

TEST(CrumpleAnalyze, RerunReplacesTheEarlierFolderWhole) {
  const fs::path dir = scratch("rerun");
  const MeshData m = synth::square_grid_mesh(4, 0.1);
  synth::write_run((dir / "good.h5").string(), m, {std::vector<double>(m.hinges.size(), 0.3)});
  const fs::path out = dir / "out";
  fs::create_directories(out);
  std::ofstream(out / "stale.csv") << "from an earlier analysis\n";
  ASSERT_EQ(run_analyze((dir / "good.h5").string() + " -o " + out.string() + "/"), 0);
  EXPECT_TRUE(fs::exists(out / "stats.json"));
  EXPECT_FALSE(fs::exists(out / "stale.csv")) << "the folder is replaced, not merged into";
  // The hidden sibling the files were written into is gone: only the run and the folder remain.
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"good.h5", "out"}));
  fs::remove_all(dir);
}

TEST(CrumpleAnalyze, VersionAndHelpFollowTheConventions) {
  const auto out = [](const std::string& args, int& code) {
    return crumple::testing::command_output(std::string(CRUMPLE_ANALYZE_EXE) + " " + args, code);
  };
  int code = -1;
  const std::string version = out("--version", code);
  EXPECT_EQ(code, 0);
  EXPECT_EQ(version.rfind(std::string("crumple-analyze ") + crumple::kVersion + " (git ", 0), 0u)
      << version;
  const std::string help = out("--help", code);
  EXPECT_EQ(code, 0);
  for (const char* part : {"--version", "Files written", "stats.json", "crease_NNNN.png",
                           "Exit codes: 0 done; 2 bad input"})
    EXPECT_NE(help.find(part), std::string::npos) << part;
}
