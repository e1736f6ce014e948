// The collapse over compaction ratios (`crumple-analyze collapse`, docs/STATISTICS.md §2.3
// step 4): from the ensemble documents of several compaction ratios (one ensemble.json per
// ratio, ensemble.hpp), the experiments' law l = c1 (1 - D) ln(1 + c2 n / D) fitted to all of
// them at once (fits/log_law.hpp fit_collapse), with the same measures (P first, then l/L0) and
// the same error model as the single-ratio fits: the increments of the ensemble means, weighted
// by their seed-to-seed s.e.m. when every point has one. The document also holds each ratio's
// own fit (copied from its ensemble) and the collapsed points x = n/D, y = mean/(1 - D) for the
// figure. Like the ensemble, this is the one implementation: the sweep report only plots and
// tabulates it.
#pragma once

#include "analysis/ensemble/ensemble.hpp"

#include <string>
#include <vector>

namespace crumple::analysis {

/// One ensemble document and where it came from.
struct EnsembleInput {
  std::string path;
  EnsembleJson doc;
};

/// Reads an ensemble.json; InputError naming the file when it is missing, not JSON, has no
/// cycles, or no single compaction ratio (its "compaction" is null: the law needs one D).
EnsembleInput read_ensemble(const std::string& path);

/// The collapse document (collapse.json) of `inputs` (at least one).
EnsembleJson collapse_json(const std::vector<EnsembleInput>& inputs);

}  // namespace crumple::analysis
