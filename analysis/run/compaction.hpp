// The compaction ratio of a run as the analysis uses it: the run file records, for every cycle,
// the ratio its compacting stage imposed (/cycles/NNNN@compaction, docs/FILE_FORMAT.md). The
// experiment's constants c1 = C/(1 - D), c2 = D/n0 (docs/STATISTICS.md §2.3) are defined for one
// compaction D, so the run's D is the value all cycles agree on; otherwise it is left unset, and
// the note says why (an older file, a cycle without a compacting stage, or cycles that differ).
#pragma once

#include "analysis/io/run_data.hpp"

#include <optional>
#include <string>
#include <vector>

namespace crumple::analysis {

struct RunCompaction {
  std::optional<double> value;  ///< D when every cycle recorded the same one
  std::string note;             ///< why value is unset; empty when it is set
};

RunCompaction run_compaction(const std::vector<CycleData>& cycles);

/// "1-3, 5, 7-8": cycle numbers (sorted) as ranges, for messages.
std::string cycle_ranges(std::vector<int> cycles);

}  // namespace crumple::analysis
