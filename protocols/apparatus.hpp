// The apparatus: geometry handed between the stages of one cycle (docs/MODEL.md §11.1); the
// roll stage leaves the roll's axis and radius, compress takes them. It is part of a checkpoint
// and writes and reads its own restart entries (sim/model/restart_data.hpp).
#pragma once

#include "sim/core/types.hpp"
#include "sim/model/restart_data.hpp"

namespace crumple {

struct Apparatus {
  bool rolled = false;
  Vec3 axis_point = Vec3::Zero();
  Vec3 axis_dir = Vec3::UnitZ();
  double radius = 0;   ///< roll radius
  double height = 0;   ///< extent of the rolled sheet along its axis (H0 of the experiment)
};

/// Adds the apparatus to `out`: @rolled, and /axis = (axis point, axis direction, radius, height).
void save_restart(const Apparatus& a, RestartData& out);
/// The apparatus stored by save_restart; InputError naming the entry when one is missing or
/// malformed.
Apparatus load_apparatus(const RestartData& in);

}  // namespace crumple
