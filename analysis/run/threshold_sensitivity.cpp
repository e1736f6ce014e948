// Threshold sensitivity table; see threshold_sensitivity.hpp.
#include "analysis/run/threshold_sensitivity.hpp"

#include "analysis/creases/threshold_rule.hpp"

namespace crumple::analysis {

ThresholdSensitivity threshold_sensitivity(const MeasureContext& ctx,
                                           const std::vector<CycleData>& cycles, double c0) {
  ThresholdSensitivity out;
  if (!(c0 > 0)) return out;
  for (double f : kSensitivityFactors) {
    out.factors.push_back(f);
    out.thresholds.push_back(f * c0);
  }
  for (const CycleData& c : cycles) {
    ThresholdSensitivity::Cycle row;
    row.cycle = c.cycle;
    for (double t : out.thresholds) {
      const CreaseMeasure m = measure_creases(ctx, c.p, t);
      row.crease_length_L0.push_back(m.length / ctx.L0);
      row.perimeter_P.push_back(m.perimeter_P);
      row.n_facets.push_back(static_cast<long>(m.seg.facets.size()));
    }
    out.cycles.push_back(std::move(row));
  }
  return out;
}

}  // namespace crumple::analysis
