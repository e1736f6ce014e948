// The stage registry and stage parameter validation: every bad stage gives file:line:column,
// the key, and what is wrong.
#include "protocols/registry.hpp"

#include <gtest/gtest.h>

using namespace crumple;

namespace {
std::string error_of(const std::string& yaml) {
  const YAML::Node n = YAML::Load(yaml);
  try {
    StageRegistry::builtin().make(n, "p.yaml", "protocol.stages[0]");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(StageRegistry, HasTheBuiltinTypes) {
  const auto names = StageRegistry::builtin().names();
  for (const char* t : {"roll", "compress", "release", "unfold", "radial_confine",
                        "spherical_stamp", "conical_pack", "fold"})
    EXPECT_NE(std::find(names.begin(), names.end(), t), names.end()) << t;
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
}

TEST(StageRegistry, UnknownTypeListsTheValidOnes) {
  const std::string e = error_of("type: squash\nspeed: 1\n");
  EXPECT_EQ(e.rfind("p.yaml:1:7: protocol.stages[0].type: unknown stage type 'squash'", 0), 0u)
      << e;
  EXPECT_NE(e.find("compress, conical_pack, fold"), std::string::npos) << e;
}

TEST(StageRegistry, MissingRequiredParameter) {
  const std::string e = error_of("type: compress\nspeed: 0.1\n");
  EXPECT_EQ(e.rfind("p.yaml:1:1: protocol.stages[0].compaction: missing required parameter", 0),
            0u)
      << e;
}

TEST(StageRegistry, NegativeSpeedIsOutOfRange) {
  const std::string e = error_of("type: compress\ncompaction: 0.3\nspeed: -2\n");
  EXPECT_EQ(e.rfind("p.yaml:3:8: protocol.stages[0].speed: must be > 0", 0), 0u) << e;
  EXPECT_NE(e.find("got -2"), std::string::npos);
}

TEST(StageRegistry, UnknownParameterListsTheValidOnes) {
  const std::string e = error_of("type: release\nthreshhold: 1e-6\n");
  EXPECT_EQ(e.rfind("p.yaml:2:1: protocol.stages[0].threshhold: unknown parameter", 0), 0u) << e;
  EXPECT_NE(e.find("threshold"), std::string::npos);
}

TEST(StageRegistry, WrongTypeAndBadChoice) {
  EXPECT_NE(error_of("type: roll\nduration: fast\n").find("expected a number, got 'fast'"),
            std::string::npos);
  EXPECT_NE(error_of("type: roll\naxis: diagonal\n").find("unknown value 'diagonal'"),
            std::string::npos);
  EXPECT_NE(error_of("type: unfold\ncontact: maybe\n").find("expected true or false"),
            std::string::npos);
}

TEST(StageRegistry, ValidStagesBuildAndDescribe) {
  EXPECT_EQ(error_of("type: compress\ncompaction: 0.27\nspeed: 0.02\n"), "");
  EXPECT_EQ(error_of("type: roll\naxis: fixed\nangle: 30\n"), "");
  EXPECT_EQ(error_of("type: roll\naxis: side\n"), "");
  const std::string d = StageRegistry::builtin().describe();
  EXPECT_NE(d.find("compaction (required)"), std::string::npos);
  EXPECT_NE(d.find("axis = random {random|fixed|side}"), std::string::npos);
}
