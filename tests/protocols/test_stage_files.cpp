// Stage self-registration: every file protocols/stages/NAME.cpp that registers a stage type
// (CRUMPLE_REGISTER_STAGE) registers exactly the type NAME, once, and each such type is in the
// registry of this test and in the one linked into crumple-sim (`--list-stages`). A stage file
// whose object the linker dropped, or a file registering under another name, fails here.
#include "protocols/registry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace crumple;

namespace {
// How many lines of the file begin with the registration macro (a mention in a comment does
// not count).
int registrations(const fs::path& file) {
  std::ifstream in(file);
  int n = 0;
  for (std::string line; std::getline(in, line);)
    n += line.rfind("CRUMPLE_REGISTER_STAGE(", 0) == 0;
  return n;
}

// The stem of every stage file that registers a type, sorted.
std::vector<std::string> registering_files() {
  std::vector<std::string> v;
  for (const auto& e : fs::directory_iterator(CRUMPLE_STAGES_DIR)) {
    if (e.path().extension() != ".cpp") continue;
    const int n = registrations(e.path());
    EXPECT_LE(n, 1) << e.path() << ": one stage type per file";
    if (n > 0) v.push_back(e.path().stem().string());
  }
  std::sort(v.begin(), v.end());
  return v;
}
}  // namespace

TEST(StageFiles, EachRegisteringFileIsOneTypeOfItsName) {
  const std::vector<std::string> files = registering_files();
  // All eight are files today; fewer means the folder was not found or the scan is broken.
  ASSERT_GE(files.size(), 8u);
  std::vector<std::string> names;
  ASSERT_NO_THROW(names = StageRegistry::builtin().names());  // a name registered twice throws
  EXPECT_EQ(names, files);
  EXPECT_EQ(registered_stage_types().size(), names.size());
}

TEST(StageFiles, CrumpleSimListsEveryType) {
  FILE* p = popen(CRUMPLE_SIM " --list-stages", "r");
  ASSERT_NE(p, nullptr);
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  ASSERT_EQ(pclose(p), 0) << out;
  // A type's line is "NAME: help"; its parameters follow, indented.
  std::vector<std::string> listed;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line[0] != ' ') listed.push_back(line.substr(0, line.find(':')));
  EXPECT_EQ(listed, registering_files()) << out;
}
