// Every protocol file in protocols/ runs as a smoke test: a tiny sheet for a short simulated
// time, through the real crumple-sim binary, giving a complete, readable run file.
#include "sim/io/run_file.hpp"
#include "tests/support/self_intersection.hpp"
#include "tests/support/scratch.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <filesystem>
#include <map>

namespace fs = std::filesystem;
using namespace crumple;

TEST(ProtocolFiles, EveryFileRunsOnATinySheet) {
  const crumple::testing::ScratchDir scratch("protocol_smoke");
  const fs::path& dir = scratch.path;
  int count = 0;
  for (const auto& entry : fs::directory_iterator("protocols")) {
    if (entry.path().extension() != ".yaml") continue;
    ++count;
    const fs::path out = dir / (entry.path().stem().string() + ".h5");
    fs::remove(out);
    const std::string cmd = std::string(CRUMPLE_SIM) + " " + entry.path().string() + " -o " +
                            out.string() +
                            // 200 nodes: quick, and fine enough for a hinge to bend to the axial
                            // protocol's 3.55 mm yield radius (refused below about 90 nodes,
                            // sim/assemble/sheet_setup.cpp).
                            " --quiet --force --threads 1 --set mesh.nodes=200 --set protocol.t_max=0.08"
                            " --set output.dt=0.02";
    SCOPED_TRACE(entry.path().string());
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    ASSERT_TRUE(fs::exists(out));
    const RunRecord r = read_run_file(out.string());
    EXPECT_GE(r.frames.size(), 2u);
    EXPECT_NE(r.meta.status.find("complete"), std::string::npos);
    EXPECT_NE(r.config.find("stages"), std::string::npos);
  }
  EXPECT_GE(count, 5) << "expected the protocol files of the issue";
}

// A whole axial-crumpling cycle through the real binary (contact as crumple-sim assembles it),
// unfolding included: no stored frame has a pair of non-adjacent triangles that intersect, and
// the run file holds the plastic field at the end of every stage.
TEST(ProtocolFiles, AxialCycleNeverPassesThroughItself) {
  const crumple::testing::ScratchDir scratch("axial_cycle");
  const fs::path& dir = scratch.path;
  const fs::path out = dir / "cycle.h5";
  fs::remove(out);
  const std::string cmd = std::string(CRUMPLE_SIM) + " protocols/axial_crumpling.yaml -o " +
                          out.string() +
                          " --quiet --force --threads 1 --seed 2 --set mesh.nodes=300"
                          " --set protocol.cycles=1 --set output.dt=0.02";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const RunRecord r = read_run_file(out.string());
  ASSERT_GT(r.frames.size(), 50u);
  std::map<std::string, int> checked;
  for (std::size_t k = 0; k < r.frames.size(); ++k) {
    const FrameRecord& f = r.frames[k];
    ++checked[f.stage];
    EXPECT_EQ(crumple::testing::count_self_intersections(r.mesh, f.state.x), 0u)
        << "frame " << k << " (" << f.stage << ", t = " << f.state.t << " s)";
  }
  for (const char* stage : {"roll", "compress", "release", "unfold"})
    EXPECT_GT(checked[stage], 2) << stage;
  ASSERT_EQ(r.stage_ends.size(), 4u);
  EXPECT_EQ(r.stage_ends[1].stage, "compress");
  EXPECT_EQ(r.stage_ends[3].p, r.cycles.at(0).p);
  // The compaction the compress stage was given (as the run resolved its configuration) is
  // recorded at its stage end and for the cycle; the other stages record none.
  const YAML::Node stage = YAML::Load(r.config)["protocol"]["stages"][1];
  ASSERT_EQ(stage["type"].as<std::string>(), "compress");
  const double given = stage["compaction"].as<double>();
  EXPECT_EQ(r.stage_ends[1].compaction, given);
  for (int k : {0, 2, 3}) EXPECT_FALSE(r.stage_ends[k].compaction.has_value()) << k;
  EXPECT_EQ(r.cycles.at(0).compaction, given);
}
