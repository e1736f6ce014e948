// The XDMF sidecars of a run file for ParaView (xdmf.cpp, docs/FILE_FORMAT.md "ParaView").
#pragma once

#include "sim/io/run_file.hpp"

#include <string>

namespace crumple {

/// Which collection of the run file an XDMF sidecar describes (docs/FILE_FORMAT.md, "ParaView").
enum class XdmfCollection {
  Frames,  ///< RUN.xdmf: every stored frame, in simulated time, the final state the last step
  Cycles,  ///< RUN.cycles.xdmf: the state at the end of each cycle, time = cycle number
};
/// An XDMF sidecar for ParaView: a temporal collection over `collection` of `h5_name`, each
/// step the sheet's surface and its hinge network (the plastic field and the crease mask on the
/// hinge edges) with cycle, stage and time as field data. Written to `xdmf_path` as it is (the
/// caller writes to a temporary name and renames); OutputError on failure, the file removed.
void write_xdmf(const std::string& xdmf_path, const std::string& h5_name, const RunRecord& r,
                XdmfCollection collection);

}  // namespace crumple
