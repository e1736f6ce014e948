// Per-stage crease accounting of one cycle: at which stage end (roll, compress, release, unfold)
// each of the cycle's new creases appeared, from the plastic fields of /stage_ends.
//
// The cycle's new creases are the hinges creased at its end and not at the previous cycle's
// end (CycleResult::new_crease_length). Each is attributed to the stage from whose end on it
// stays creased up to the last stage end of the cycle. So a hinge that is creased at one stage
// end, falls back below the threshold at the next (an unfolding that flattens it) and is creased
// again later counts once, at the later stage, and the stages' new lengths add up exactly to the
// cycle's new length whenever the last stage end is the cycle end. A plain difference of
// successive crease sets would count such a hinge twice and could exceed the cycle's total.
// What falls back below the threshold at a stage end is reported separately (lost_length).
#pragma once

#include "analysis/creases/crease_band.hpp"
#include "analysis/io/run_data.hpp"

#include <optional>
#include <string>
#include <vector>

namespace crumple::analysis {

struct StageCreases {
  int index = 0;             ///< stage_index: position of the stage in its cycle
  std::string stage;         ///< stage type
  double t = 0.0;            ///< time of the stage end
  long crease_edges = 0;     ///< hinges creased at the stage end
  double crease_length = 0;  ///< crease length at the stage end (cumulative), length units
  double new_length = 0;     ///< the part of the cycle's new crease length that appeared here
  double lost_length = 0;    ///< creased at the previous stage end (or cycle end), not here
};

/// `stages`: one cycle's stage ends in run order (may be empty). `cycle_end`: hinges creased at
/// the cycle's end; `previous_end`: at the previous cycle's end (empty before cycle 1, meaning
/// none). Lengths are in the mesh's length units.
std::vector<StageCreases> account_stages(const MeshData& mesh,
                                         const std::vector<const StageEndData*>& stages,
                                         const std::vector<char>& cycle_end,
                                         const std::vector<char>& previous_end, double threshold,
                                         const CreaseBand* band = nullptr);

/// Share of `cycle_new_length` made at the stage ends after the last one of type `stage_type`;
/// nullopt without stages, without such a stage, or when cycle_new_length is not positive.
std::optional<double> share_after_last(const std::vector<StageCreases>& stages,
                                       const std::string& stage_type, double cycle_new_length);

}  // namespace crumple::analysis
