// Where crumple-sim writes, checked before anything is computed (README.md, "Running the
// simulator"): the run file RUN.h5, its checkpoint RUN.h5.tmp (renamed to RUN.h5 at the end)
// and the XDMF sidecars RUN.xdmf (the frames) and RUN.cycles.xdmf (the cycle ends). Each must
// be a regular file or absent, in a directory that exists and takes new files; the sidecar must
// not be the run file. An existing run file or sidecar is replaced only with --force, by the
// longer run of --extend, or by a pending checkpoint's run continued with --resume (begun by one
// of those two); a pending checkpoint is continued with --resume or discarded with --force,
// never silently.
#pragma once

#include <string>

namespace crumple {

struct OutputPaths {
  std::string run, tmp, xdmf, xdmf_cycles;  ///< xdmf, xdmf_cycles empty: no sidecars
};

/// InputError "-o PATH: what is wrong" (exit 2) when the run cannot write where it is asked to.
/// `extend`: the run file and its sidecars are the run being extended, replaced at its end.
OutputPaths check_output_paths(const std::string& run, bool xdmf, bool resume, bool force,
                               bool extend = false);

}  // namespace crumple
