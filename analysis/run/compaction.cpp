// The run's compaction ratio from the per-cycle records; see compaction.hpp.
#include "analysis/run/compaction.hpp"

#include <algorithm>
#include <map>
#include <sstream>

namespace crumple::analysis {

std::string cycle_ranges(std::vector<int> cycles) {
  std::sort(cycles.begin(), cycles.end());
  std::ostringstream os;
  for (std::size_t i = 0; i < cycles.size();) {
    std::size_t j = i;
    while (j + 1 < cycles.size() && cycles[j + 1] == cycles[j] + 1) ++j;
    os << (i ? ", " : "") << cycles[i];
    if (j > i) os << "-" << cycles[j];
    i = j + 1;
  }
  return os.str();
}

RunCompaction run_compaction(const std::vector<CycleData>& cycles) {
  RunCompaction out;
  std::vector<int> unrecorded, uncompacted;
  std::map<double, std::vector<int>> by_value;
  for (const auto& c : cycles) {
    if (!c.compaction_recorded)
      unrecorded.push_back(c.cycle);
    else if (!c.compaction)
      uncompacted.push_back(c.cycle);
    else
      by_value[*c.compaction].push_back(c.cycle);
  }
  const std::string unset = ": c1 and c2 (docs/STATISTICS.md §2.3) are not computed";
  if (unrecorded.size() == cycles.size()) {
    out.note = "the run file records no compaction ratio (/cycles/NNNN@compaction; a file "
               "written before crumple-sim recorded it)" + unset;
  } else if (!unrecorded.empty()) {
    out.note = "the run file records no compaction ratio for cycle(s) " +
               cycle_ranges(unrecorded) + unset;
  } else if (!uncompacted.empty()) {
    out.note = "no stage of cycle(s) " + cycle_ranges(uncompacted) +
               " compacts the sheet (no compaction ratio recorded)" + unset;
  } else if (by_value.size() > 1) {
    std::ostringstream os;
    os << "the compaction ratio differs from cycle to cycle (";
    bool first = true;
    for (const auto& [d, cs] : by_value) {
      os << (first ? "" : "; ") << d << " in cycle(s) " << cycle_ranges(cs);
      first = false;
    }
    os << "); c1 and c2 are defined for one compaction and are not computed";
    out.note = os.str();
  } else if (by_value.size() == 1) {
    out.value = by_value.begin()->first;
  }
  return out;
}

}  // namespace crumple::analysis
