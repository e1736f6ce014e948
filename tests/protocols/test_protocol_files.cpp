// Every protocol file in protocols/ runs as a smoke test: a tiny sheet for a short simulated
// time, through the real crumple-sim binary, giving a complete, readable run file
// (STYLE.md habit 10).
#include "sim/io/run_file.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;
using namespace crumple;

TEST(ProtocolFiles, EveryFileRunsOnATinySheet) {
  const fs::path dir = fs::temp_directory_path() / "crumple_protocol_smoke";
  fs::create_directories(dir);
  int count = 0;
  for (const auto& entry : fs::directory_iterator("protocols")) {
    if (entry.path().extension() != ".yaml") continue;
    ++count;
    const fs::path out = dir / (entry.path().stem().string() + ".h5");
    fs::remove(out);
    const std::string cmd = std::string(CRUMPLE_SIM) + " " + entry.path().string() + " -o " +
                            out.string() +
                            " --quiet --threads 1 --set mesh.nodes=80 --set protocol.t_max=0.08"
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
