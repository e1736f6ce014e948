// One crease measurement; see crease_measure.hpp.
#include "analysis/run/crease_measure.hpp"

#include "analysis/creases/crease_edges.hpp"
#include "analysis/raster/crease_map.hpp"

namespace crumple::analysis {

CreaseMeasure measure_creases(const MeasureContext& ctx, const std::vector<double>& p,
                              double threshold) {
  CreaseMeasure m;
  m.creased = select_creases(p, threshold, ctx.band);
  for (char f : m.creased) m.crease_edges += f;
  m.length = crease_length(*ctx.mesh, m.creased);
  m.seg = segment_facets(ctx.sheet, crease_layer(*ctx.mesh, m.creased, ctx.frame, ctx.crease_px),
                         ctx.segment);
  m.perimeter_P = perimeter_crease_length(m.seg, ctx.L0_px);
  return m;
}

}  // namespace crumple::analysis
