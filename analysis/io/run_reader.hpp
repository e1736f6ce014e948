// Thin HDF5 reader of a run file (docs/FILE_FORMAT.md): /meta, /config, /mesh, /cycles and the
// optional /stage_ends.
//
// It checks every shape it relies on and throws InputError naming the file and the missing or
// malformed object, so the caller can exit with code 2 before writing anything.
#pragma once

#include "analysis/io/run_data.hpp"

#include <stdexcept>
#include <string>

namespace crumple::analysis {

/// Bad input: a missing file, a file that is not HDF5, missing groups/datasets, wrong shapes.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Reads and validates the run file at `path`. /meta, /config and /stage_ends are optional (a
/// warning is recorded when absent); /mesh and at least one /cycles/NNNN group are required.
RunData read_run(const std::string& path);

}  // namespace crumple::analysis
