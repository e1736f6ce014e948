// What `crumple-sim --resume` accepts (README.md, "Checkpoints and resume"): the checkpoint must
// fit the run's mesh and protocol, and the configuration given on the command line must be the
// run's own except for the keys that steer the numerics or the output without changing the
// problem (the keys the schema marks may_change_on_resume: resumable_keys(), config_schema.hpp).
// Those are applied from the checkpoint on and recorded in /resumes. `crumple-sim --extend`
// continues a complete run from the checkpoint it ends with (the state after its last cycle)
// under the same policy, with one more key free to change: protocol.cycles, upward.
#pragma once

#include "protocols/checkpoint.hpp"
#include "sim/io/params.hpp"
#include "sim/io/run_file.hpp"

#include <string>
#include <vector>

namespace crumple {

/// The keys whose values differ between `stored` (the run's configuration) and `given` (the
/// command line's), as "key: OLD -> NEW", if all of them are resumable (and, when `extending`,
/// protocol.cycles if it grows); otherwise an InputError naming `source` (the file resumed or
/// extended), where each offending new value was set, and both values.
std::vector<std::string> resume_changes(const Params& stored, const Params& given,
                                        const std::string& source, bool extending = false);

/// The keys of `given` that `stored_text` (a run file's /config as stored) lacks: the program
/// gained them after the run started, and they take their given value from the checkpoint on,
/// as "key: (absent: ...) -> NEW".
std::vector<std::string> keys_added_since(const std::string& stored_text, const Params& given);

/// The stored checkpoint, checked against the protocol of `p` (cycle and stage in range) and
/// its integrator history against the mesh (vector lengths); InputError naming `tmp` and the
/// entry at fault.
Checkpoint checkpoint_to_resume(const RunRecord& rec, const Params& p, const std::string& tmp);

/// For --extend: the checkpoint a complete run `rec` (read from `path`, configuration `stored`)
/// ends with, at the start of cycle stored.protocol.cycles + 1, checked as checkpoint_to_resume
/// does against `given`. The frame a run adds at its very end when that end is off the frame
/// grid (ProtocolRunner::run) is dropped from `rec`, so that the extended run's frames are those
/// of a run that had been given the larger cycle count from the start. InputError naming `path`
/// when the run is not complete or does not end at a cycle's end.
Checkpoint checkpoint_to_extend(RunRecord& rec, const Params& stored, const Params& given,
                                const std::string& path);

}  // namespace crumple
