// How much the crease measures depend on the crease threshold: per cycle, the plastic-edge
// length, the perimeter length P and the facet count at thresholds F c0 for the factors
// kSensitivityFactors (creases/threshold_rule.hpp), with the maps segmented again at every
// threshold. No facet-shape fits or bootstraps here: the table is meant to stay cheap.
#pragma once

#include "analysis/run/crease_measure.hpp"

#include <vector>

namespace crumple::analysis {

struct ThresholdSensitivity {
  std::vector<double> factors;     ///< F, in the order of kSensitivityFactors
  std::vector<double> thresholds;  ///< F c0
  struct Cycle {
    int cycle = 0;
    std::vector<double> crease_length_L0, perimeter_P;  ///< one per threshold
    std::vector<long> n_facets;
  };
  std::vector<Cycle> cycles;
};

/// Empty (no factors) when c0 is not positive.
ThresholdSensitivity threshold_sensitivity(const MeasureContext& ctx,
                                           const std::vector<CycleData>& cycles, double c0);

}  // namespace crumple::analysis
