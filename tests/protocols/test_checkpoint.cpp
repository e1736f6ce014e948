// The checkpoint's restart entries: every field of the runner's checkpoint and the apparatus
// comes back exactly from its entries (the run file stores them, tests/io/test_run_file.cpp), a
// checkpoint taken between stages carries no stage-begin state, and a missing or malformed
// entry is an InputError naming it.
#include "protocols/checkpoint.hpp"
#include "sim/core/errors.hpp"

#include <gtest/gtest.h>

using namespace crumple;

namespace {

State some_state(double t) {
  State s;
  s.x = VecX::LinSpaced(6, 0.0, 1.0);
  s.v = VecX::Constant(6, -t);
  s.p = VecX::LinSpaced(2, -0.5, 0.25);
  s.t = t;
  return s;
}

Checkpoint some_checkpoint() {
  Checkpoint c;
  c.cycle = 3, c.stage = 2, c.in_stage = true, c.stage_t_begin = 1.25, c.next_frame_t = 1.3;
  c.stage_begin = some_state(1.25);
  c.state = some_state(1.28);
  c.rng_at_stage_begin = "12 34 56";
  c.contact_at_stage_begin = false;
  c.stepper = {1, 2, 3.5};
  c.apparatus.rolled = true;
  c.apparatus.axis_point = Vec3(0.1, 0.2, 0.3);
  c.apparatus.axis_dir = Vec3(0, 1, 0);
  c.apparatus.radius = 0.0177;
  c.apparatus.height = 0.21;
  return c;
}

std::string message_of(const RestartData& d) {
  try {
    (void)load_checkpoint(d);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Checkpoint, RestartEntriesRoundTripExactly) {
  const Checkpoint c = some_checkpoint();
  const Checkpoint q = load_checkpoint(save_restart(c));
  EXPECT_EQ(q.cycle, 3);
  EXPECT_EQ(q.stage, 2);
  EXPECT_TRUE(q.in_stage);
  EXPECT_EQ(q.stage_t_begin, 1.25);
  EXPECT_EQ(q.next_frame_t, 1.3);
  EXPECT_EQ(q.stage_begin.x, c.stage_begin.x);
  EXPECT_EQ(q.stage_begin.t, 1.25);
  EXPECT_EQ(q.state.v, c.state.v);
  EXPECT_EQ(q.state.p, c.state.p);
  EXPECT_EQ(q.rng_at_stage_begin, "12 34 56");
  EXPECT_FALSE(q.contact_at_stage_begin);
  EXPECT_EQ(q.stepper, c.stepper);
  EXPECT_TRUE(q.apparatus.rolled);
  EXPECT_EQ(q.apparatus.axis_point, c.apparatus.axis_point);
  EXPECT_EQ(q.apparatus.axis_dir, c.apparatus.axis_dir);
  EXPECT_EQ(q.apparatus.radius, 0.0177);
  EXPECT_EQ(q.apparatus.height, 0.21);
}

// The entry names are the run file's /checkpoint layout (docs/FILE_FORMAT.md); files written
// before the checkpoint's parts owned their entries must still resume.
TEST(Checkpoint, EntriesAreTheFileLayout) {
  const RestartData d = save_restart(some_checkpoint());
  for (const char* k : {"cycle", "stage", "in_stage", "contact_at_stage_begin", "rolled"})
    EXPECT_EQ(d.ints.count(k), 1u) << k;
  for (const char* k : {"stage_t_begin", "next_frame_t"}) EXPECT_EQ(d.reals.count(k), 1u) << k;
  EXPECT_EQ(d.texts.count("rng_at_stage_begin"), 1u);
  EXPECT_EQ(d.arrays.count("stepper"), 1u);
  EXPECT_EQ(d.arrays.at("axis").size(), 8u);
  EXPECT_EQ(d.states.count("state"), 1u);
  EXPECT_EQ(d.states.count("stage_begin"), 1u);
}

TEST(Checkpoint, BetweenStagesThereIsNoStageBeginState) {
  Checkpoint c = some_checkpoint();
  c.in_stage = false;
  const RestartData d = save_restart(c);
  EXPECT_FALSE(d.has_state("stage_begin"));
  EXPECT_FALSE(load_checkpoint(d).in_stage);
}

TEST(Checkpoint, MissingOrMalformedEntriesAreNamed) {
  const RestartData good = save_restart(some_checkpoint());
  RestartData d = good;
  d.origin = "run.h5.tmp: /checkpoint";
  d.ints.erase("cycle");
  EXPECT_EQ(message_of(d), "run.h5.tmp: /checkpoint@cycle: missing");
  d = good;
  d.arrays["axis"].pop_back();
  EXPECT_EQ(message_of(d), "/checkpoint/axis: expected 8 values");
  d = good;
  d.states.erase("stage_begin");  // in a stage, the stage's start is needed
  EXPECT_EQ(message_of(d), "/checkpoint/stage_begin: missing");
  d = good;
  d.ints["cycle"] = 0;
  EXPECT_EQ(message_of(d), "/checkpoint@cycle: must be >= 1");
  d = good;
  d.ints["stage"] = -1;
  EXPECT_EQ(message_of(d), "/checkpoint@stage: must be >= 0");
  d = good;
  d.reals.erase("next_frame_t");
  EXPECT_EQ(message_of(d), "/checkpoint@next_frame_t: missing");
}
