// The protocol's checkpoint: everything the runner needs to continue a run (docs/MODEL.md §11.1),
// and its restart entries (sim/model/restart_data.hpp). The run file stores the entries under
// /checkpoint (docs/FILE_FORMAT.md) and knows nothing of what they mean; each part writes its
// own: the runner its position in the protocol, the apparatus its geometry (apparatus.hpp), the
// stepper its history as numbers it alone decodes (Stepper::save).
#pragma once

#include "protocols/apparatus.hpp"
#include "sim/model/restart_data.hpp"

#include <string>
#include <vector>

namespace crumple {

struct Checkpoint {
  int cycle = 1;              ///< 1-based
  int stage = 0;              ///< index of the stage in the cycle
  bool in_stage = false;      ///< false: taken before the stage began
  double stage_t_begin = 0;
  State stage_begin;          ///< the state when the stage began (in_stage only)
  std::string rng_at_stage_begin;
  bool contact_at_stage_begin = true;
  Apparatus apparatus;
  State state;
  std::vector<double> stepper;
  double next_frame_t = 0;
};

/// The checkpoint as restart entries: @cycle, @stage, @in_stage, @stage_t_begin,
/// @rng_at_stage_begin, @contact_at_stage_begin, @next_frame_t, /state, /stage_begin (in_stage
/// only), /stepper, and the apparatus's.
RestartData save_restart(const Checkpoint& c);
/// The checkpoint stored by save_restart; InputError naming the entry when one is missing or out
/// of its range (cycle >= 1, stage >= 0). Whether cycle and stage fit the protocol, and the
/// stepper's numbers the stepper, is the caller's check.
Checkpoint load_checkpoint(const RestartData& in);

}  // namespace crumple
