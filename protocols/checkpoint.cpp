// The checkpoint's restart entries (checkpoint.hpp).
#include "protocols/checkpoint.hpp"

namespace crumple {

RestartData save_restart(const Checkpoint& c) {
  RestartData d;
  d.ints["cycle"] = c.cycle;
  d.ints["stage"] = c.stage;
  d.ints["in_stage"] = c.in_stage;
  d.ints["contact_at_stage_begin"] = c.contact_at_stage_begin;
  d.reals["stage_t_begin"] = c.stage_t_begin;
  d.reals["next_frame_t"] = c.next_frame_t;
  d.texts["rng_at_stage_begin"] = c.rng_at_stage_begin;
  d.states["state"] = c.state;
  if (c.in_stage) d.states["stage_begin"] = c.stage_begin;
  d.arrays["stepper"] = c.stepper;
  save_restart(c.apparatus, d);
  return d;
}

Checkpoint load_checkpoint(const RestartData& in) {
  Checkpoint c;
  c.state = in.state("state");
  c.in_stage = in.integer("in_stage") != 0;
  if (c.in_stage) c.stage_begin = in.state("stage_begin");
  c.stepper = in.array("stepper");
  c.cycle = static_cast<int>(in.integer("cycle"));
  c.stage = static_cast<int>(in.integer("stage"));
  c.stage_t_begin = in.real("stage_t_begin");
  c.rng_at_stage_begin = in.text("rng_at_stage_begin");
  c.contact_at_stage_begin = in.integer("contact_at_stage_begin") != 0;
  c.next_frame_t = in.real("next_frame_t");
  c.apparatus = load_apparatus(in);
  if (c.cycle < 1) in.fail("@cycle", "must be >= 1");
  if (c.stage < 0) in.fail("@stage", "must be >= 0");
  return c;
}

}  // namespace crumple
