// Reading of the optional /stage_ends group of a run file (docs/FILE_FORMAT.md): the plastic
// field at the end of every finished protocol stage, which the per-stage crease accounting needs.
// Internal to the analysis library; read_run() calls it.
#pragma once

#include "analysis/io/h5_checked.hpp"
#include "analysis/io/run_data.hpp"

namespace crumple::analysis {

/// Fills run.stage_ends (run order, i.e. by the group's 6-digit counter) and sets
/// run.has_stage_ends. A file without /stage_ends is an older file, not a bad one: it gets a
/// warning and no per-stage data. A malformed record (wrong p shape, missing attribute) fails.
void read_stage_ends(const H5::H5File& file, const h5::Reader& r, hsize_t hinges, RunData& run);

}  // namespace crumple::analysis
